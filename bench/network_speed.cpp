// network_speed.cpp: how fast the denoising network runs, in one run: each
// quality's three UNets (the main network and the albedo and normal
// prefilters) at 1920x1088 (1080p padded to the network's alignment), the
// best of several runs after a warm-up that also builds the plan; against
// the largest convolution of each network run alone with oneDNN (same
// resolution, stored channels, blocked layout and fused ReLU as the plan),
// and against the FP32 FMA peak of the same threads, measured with a small
// register-only kernel. Prints markdown tables for docs/benchmarks.md and
// the load average before and after.
//
// Usage: network_speed [--weights DIR] [--runs N] [--threads T[,T...]]
//   DIR  the .tza files (default build/weights); N runs after the warm-up
//   (default 3); T the thread counts to measure, e.g. 2,1 (default 2).
#include "network/thread_count.h"
#include "network/unet.h"
#include "network/unet_plan.h"

#include <oneapi/dnnl/dnnl.hpp>

#include <immintrin.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;
using mcdenoise::UNet;
using mcdenoise::UNetConv;
using mcdenoise::UNetLayout;

constexpr int bench_height = 1088;
constexpr int bench_width  = 1920;

double seconds_since(Clock::time_point start)
{
    return std::chrono::duration<double>(Clock::now() - start).count();
}

/// The 1, 5 and 15 minute load averages, as /proc/loadavg gives them.
std::string load_average()
{
    std::ifstream file("/proc/loadavg");
    std::string one, five, fifteen;
    file >> one >> five >> fifteen;
    return one + ", " + five + ", " + fifteen;
}

[[noreturn]] void fail(const std::string& message)
{
    std::fprintf(stderr, "network_speed: %s\n", message.c_str());
    std::exit(1);
}

// ---------------------------------------------------------------- FMA peak

/// Floating-point operations per iteration of the FMA kernels: independent
/// chains x lanes x 2 (a multiply-add counts 2, as in flops_per_pixel).
constexpr int avx512_chains = 16;
constexpr int avx2_chains   = 10;

/// `iterations` steps of `avx512_chains` independent FMA chains on 16-float
/// registers (enough chains to cover the FMA latency on two ports); returns
/// their sum so that the work is kept.
__attribute__((target("avx512f"))) float fma_chains_avx512(long iterations)
{
    __m512 acc[avx512_chains];
    for (int c = 0; c < avx512_chains; ++c)
        acc[c] = _mm512_set1_ps(0.001f * float(c));
    const __m512 a = _mm512_set1_ps(0.999999f);
    const __m512 b = _mm512_set1_ps(1e-7f);
    for (long i = 0; i < iterations; ++i)
        for (int c = 0; c < avx512_chains; ++c)
            acc[c] = _mm512_fmadd_ps(acc[c], a, b);
    __m512 sum = acc[0];
    for (int c = 1; c < avx512_chains; ++c)
        sum = _mm512_add_ps(sum, acc[c]);
    float lanes[16];
    _mm512_storeu_ps(lanes, sum);
    float total = 0.0f;
    for (float lane : lanes)
        total += lane;
    return total;
}

/// As fma_chains_avx512 on 8-float AVX2 registers (16 of them: the chains
/// and the two constants fit).
__attribute__((target("avx2,fma"))) float fma_chains_avx2(long iterations)
{
    __m256 acc[avx2_chains];
    for (int c = 0; c < avx2_chains; ++c)
        acc[c] = _mm256_set1_ps(0.001f * float(c));
    const __m256 a = _mm256_set1_ps(0.999999f);
    const __m256 b = _mm256_set1_ps(1e-7f);
    for (long i = 0; i < iterations; ++i)
        for (int c = 0; c < avx2_chains; ++c)
            acc[c] = _mm256_fmadd_ps(acc[c], a, b);
    __m256 sum = acc[0];
    for (int c = 1; c < avx2_chains; ++c)
        sum = _mm256_add_ps(sum, acc[c]);
    float lanes[8];
    _mm256_storeu_ps(lanes, sum);
    float total = 0.0f;
    for (float lane : lanes)
        total += lane;
    return total;
}

/// The FP32 FMA peak of `nthreads` threads in GFLOP/s (the best of 3), and
/// the instruction set it was measured with; 0 without AVX2.
struct Peak {
    double gflops   = 0.0;
    const char* isa = "none (no AVX2)";
};

Peak fma_peak(int nthreads)
{
    Peak peak;
    const bool avx512 = __builtin_cpu_supports("avx512f");
    if (!avx512 && !(__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")))
        return peak;
    peak.isa                    = avx512 ? "AVX-512" : "AVX2";
    const long iterations       = 40'000'000;
    const double flops_per_iter = avx512 ? avx512_chains * 16 * 2 : avx2_chains * 8 * 2;
    std::atomic<float> sink { 0.0f };  // keeps the kernels' results
    for (int repeat = 0; repeat < 3; ++repeat) {
        std::atomic<bool> go { false };
        std::vector<std::thread> threads;
        for (int t = 0; t < nthreads; ++t)
            threads.emplace_back([&] {
                while (!go.load())
                    std::this_thread::yield();
                const float r =
                    avx512 ? fma_chains_avx512(iterations) : fma_chains_avx2(iterations);
                sink.store(r);
            });
        const auto start = Clock::now();
        go.store(true);
        for (std::thread& t : threads)
            t.join();
        const double seconds = seconds_since(start);
        peak.gflops =
            std::max(peak.gflops, nthreads * iterations * flops_per_iter / seconds * 1e-9);
    }
    return peak;
}

// ------------------------------------------------------ the largest layer

/// One convolution of a network, where the plan runs it: its level and
/// the channels as stored (each concatenated part padded to the channel
/// block).
struct Layer {
    std::string name;
    int level      = 0;
    int stored_in  = 0;
    int stored_out = 0;
    double flops   = 0.0;  // at bench_width x bench_height, logical channels
};

int padded(int channels, int block) { return (channels + block - 1) / block * block; }

/// The convolution of `layout` with the most FLOPs at the bench size.
Layer largest_layer(const UNetLayout& layout, int block)
{
    Layer best;
    const double pixels = double(bench_width) * bench_height;
    for (int level = 0; level < int(layout.levels.size()); ++level) {
        const auto& encoder = layout.levels[level].encoder;
        const auto& decoder = layout.levels[level].decoder;
        std::vector<const UNetConv*> convs;
        for (const UNetConv& c : encoder)
            convs.push_back(&c);
        for (const UNetConv& c : decoder)
            convs.push_back(&c);
        for (const UNetConv* c : convs) {
            const double flops =
                2.0 * 9 * c->in_channels * c->out_channels * pixels / double(1 << (2 * level));
            if (flops <= best.flops)
                continue;
            // A decoder's first convolution reads [upsampled, level input],
            // each part padded on its own.
            const int stored = !decoder.empty() && c == &decoder.front()
                                   ? padded(layout.upsampled_channels(level), block)
                                         + padded(layout.level_input_channels(level), block)
                                   : padded(c->in_channels, block);
            best             = { c->name, level, stored, padded(c->out_channels, block), flops };
        }
    }
    return best;
}

/// The speed of one layer run alone: GFLOP/s (its logical FLOPs over the
/// best time) and oneDNN's implementation.
struct LayerSpeed {
    double gflops = 0.0;
    std::string impl;
};

/// Runs `layer` alone with oneDNN as unet_plan.cpp does (3x3, padding 1,
/// bias, fused ReLU, nChw16c / nChw8c source and destination, weights in
/// the layout the primitive picks) on random data at its level's
/// resolution of the bench size: a warm-up, then the best of `runs`.
LayerSpeed time_layer(const Layer& layer, int block, int runs, int nthreads)
{
    using dnnl::memory;
    const mcdenoise::ScopedThreadCount threads(nthreads);
    const dnnl::engine engine(dnnl::engine::kind::cpu, 0);
    dnnl::stream stream(engine);
    const int out       = layer.stored_out;
    const memory::dim h = bench_height >> layer.level, w = bench_width >> layer.level;
    const auto tag = block == 16 ? memory::format_tag::nChw16c : memory::format_tag::nChw8c;
    const memory::desc src_desc({ 1, layer.stored_in, h, w }, memory::data_type::f32, tag);
    const memory::desc dst_desc({ 1, out, h, w }, memory::data_type::f32, tag);
    const memory::desc weights_desc({ out, layer.stored_in, 3, 3 }, memory::data_type::f32,
                                    memory::format_tag::any);
    const memory::desc bias_desc({ out }, memory::data_type::f32, memory::format_tag::x);
    dnnl::post_ops post;
    post.append_eltwise(1.0f, dnnl::algorithm::eltwise_relu, 0.0f, 0.0f);
    dnnl::primitive_attr attr;
    attr.set_post_ops(post);
    const dnnl::convolution_forward::desc d(
        dnnl::prop_kind::forward_inference, dnnl::algorithm::convolution_direct, src_desc,
        weights_desc, bias_desc, dst_desc, { 1, 1 }, { 1, 1 }, { 1, 1 });
    const dnnl::convolution_forward::primitive_desc pd(d, attr, engine);

    std::mt19937 random(7);
    std::uniform_real_distribution<float> uniform(-0.05f, 0.05f);
    const auto filled = [&](const memory::desc& desc, float offset) {
        memory m(desc, engine);
        float* data = static_cast<float*>(m.get_data_handle());
        for (size_t i = 0; i < desc.get_size() / sizeof(float); ++i)
            data[i] = uniform(random) + offset;
        return m;
    };
    const memory src = filled(src_desc, 0.05f), weights = filled(pd.weights_desc(), 0.0f),
                 bias = filled(bias_desc, 0.0f), dst = filled(dst_desc, 0.0f);
    const dnnl::convolution_forward conv(pd);
    double best = 1e30;
    for (int run = 0; run <= runs; ++run) {
        const auto start = Clock::now();
        conv.execute(stream, { { DNNL_ARG_SRC, src },
                               { DNNL_ARG_WEIGHTS, weights },
                               { DNNL_ARG_BIAS, bias },
                               { DNNL_ARG_DST, dst } });
        stream.wait();
        if (run > 0)
            best = std::min(best, seconds_since(start));
    }
    return { layer.flops / best * 1e-9, pd.impl_info_str() };
}

// ------------------------------------------------------------- networks

/// One network of a quality and what was measured of it.
struct Network {
    std::string file, path;
    int input_channels  = 0;
    double best_seconds = 1e30;
    double flops        = 0.0;
    size_t working      = 0;
    Layer largest;
    LayerSpeed largest_speed;
};

/// A quality: its main network and its albedo and normal prefilters.
struct Quality {
    std::string name;
    std::vector<Network> networks;
    double best_seconds = 1e30;  // the three run one after the other
};

std::vector<float> random_planes(int channels)
{
    std::mt19937 random(1);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    std::vector<float> planes(size_t(channels) * bench_width * bench_height);
    for (float& v : planes)
        v = uniform(random);
    return planes;
}

/// Loads the network at `path`; exits if it cannot.
UNet load(const std::string& path)
{
    UNet unet;
    std::string error;
    if (!unet.load(path, error))
        fail(error);
    return unet;
}

/// Measures every network of `qualities` on `nthreads` threads and prints
/// the tables. Each quality's networks are loaded for its measurement
/// only, so that at most three plans (high's: gigabytes) are held at once.
void measure(std::vector<Quality>& qualities, int runs, int nthreads, int block)
{
    const double pixels = double(bench_width) * bench_height;
    std::vector<float> output(size_t(mcdenoise::unet_output_channels) * bench_width * bench_height);
    std::string error;
    for (Quality& q : qualities) {
        q.best_seconds = 1e30;
        std::vector<UNet> unets;
        std::vector<std::vector<float>> inputs;
        for (Network& n : q.networks) {
            n.best_seconds = 1e30;
            unets.push_back(load(n.path));
            inputs.push_back(random_planes(n.input_channels));
        }
        for (int run = 0; run <= runs; ++run) {  // run 0: the warm-up, which plans
            double total = 0.0;
            for (size_t i = 0; i < q.networks.size(); ++i) {
                Network& n       = q.networks[i];
                const auto start = Clock::now();
                if (!unets[i].run(inputs[i].data(), bench_height, bench_width, output.data(),
                                  nthreads, error))
                    fail(n.file + ": " + error);
                const double seconds = seconds_since(start);
                total += seconds;
                if (run > 0)
                    n.best_seconds = std::min(n.best_seconds, seconds);
            }
            if (run > 0)
                q.best_seconds = std::min(q.best_seconds, total);
        }
        for (Network& n : q.networks)
            n.largest_speed = time_layer(n.largest, block, runs, nthreads);
    }

    const Peak peak = fma_peak(nthreads);
    std::printf("\n## %d thread%s\n\nFP32 FMA peak (%s, %d thread%s): %.1f GFLOP/s\n\n", nthreads,
                nthreads == 1 ? "" : "s", peak.isa, nthreads, nthreads == 1 ? "" : "s",
                peak.gflops);
    const auto of_peak = [&](double gflops) {
        char text[32];
        std::snprintf(text, sizeof text, "%.2f", gflops / peak.gflops);
        return peak.gflops > 0 ? std::string(text) : std::string("-");
    };

    std::printf(
        "| quality | network | s | GFLOP | GFLOP/s | largest layer (stored in -> out, level) "
        "| its GFLOP/s alone | network / layer | / FMA peak | working bytes per pixel |\n"
        "|---|---|---|---|---|---|---|---|---|---|\n");
    for (const Quality& q : qualities)
        for (const Network& n : q.networks) {
            const double gflops = n.flops / n.best_seconds * 1e-9;
            std::printf(
                "| %s | %s | %.3f | %.1f | %.1f | %s (%d -> %d, %d) | %.1f | %.2f | %s | %.0f |\n",
                q.name.c_str(), n.file.c_str(), n.best_seconds, n.flops * 1e-9, gflops,
                n.largest.name.c_str(), n.largest.stored_in, n.largest.stored_out, n.largest.level,
                n.largest_speed.gflops, gflops / n.largest_speed.gflops, of_peak(gflops).c_str(),
                double(n.working) / pixels);
        }
    std::printf("\nLargest layers' oneDNN implementations:");
    for (const Quality& q : qualities)
        for (const Network& n : q.networks)
            std::printf(" %s %s: %s;", n.file.c_str(), n.largest.name.c_str(),
                        n.largest_speed.impl.c_str());
    std::printf("\n\n");

    std::printf("| quality | s at 1080p, %d thread%s (3 networks) | GFLOP | GFLOP/s "
                "| / largest layer alone | / FMA peak | working bytes per pixel |\n"
                "|---|---|---|---|---|---|---|\n",
                nthreads, nthreads == 1 ? "" : "s");
    for (const Quality& q : qualities) {
        double flops = 0.0, working = 0.0;
        const Network* largest = &q.networks.front();
        for (const Network& n : q.networks) {
            flops += n.flops;
            working += double(n.working);
            if (n.largest.flops > largest->largest.flops)
                largest = &n;
        }
        const double gflops = flops / q.best_seconds * 1e-9;
        std::printf("| %s | %.2f | %.0f | %.1f | %.2f | %s | %.0f |\n", q.name.c_str(),
                    q.best_seconds, flops * 1e-9, gflops, gflops / largest->largest_speed.gflops,
                    of_peak(gflops).c_str(), working / pixels);
    }
}

}  // namespace

int main(int argc, char** argv)
{
    std::string weights = "build/weights", thread_list = "2";
    int runs   = 3;
    bool usage = false;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--weights" && i + 1 < argc)
            weights = argv[++i];
        else if (a == "--runs" && i + 1 < argc)
            runs = std::atoi(argv[++i]);
        else if (a == "--threads" && i + 1 < argc)
            thread_list = argv[++i];
        else
            usage = true;
    }
    std::vector<int> thread_counts;
    std::stringstream list(thread_list);
    for (std::string item; std::getline(list, item, ',');)
        thread_counts.push_back(std::atoi(item.c_str()));
    if (usage || runs < 1 || thread_counts.empty()
        || *std::min_element(thread_counts.begin(), thread_counts.end()) < 1) {
        std::fprintf(stderr,
                     "usage: network_speed [--weights DIR] [--runs N] [--threads T[,T...]]\n");
        return 2;
    }

    const std::string load_before = load_average();
    const int block               = mcdenoise::unet_channel_block();
    const double pixels           = double(bench_width) * bench_height;
    std::vector<Quality> qualities(3);
    qualities[0].name       = "fast";
    qualities[1].name       = "balanced";
    qualities[2].name       = "high";
    const char* files[3][3] = { { "rt_hdr_calb_cnrm_small.tza", "rt_alb.tza", "rt_nrm.tza" },
                                { "rt_hdr_calb_cnrm.tza", "rt_alb.tza", "rt_nrm.tza" },
                                { "rt_hdr_calb_cnrm_large.tza", "rt_alb_large.tza",
                                  "rt_nrm_large.tza" } };
    std::string error;
    for (int q = 0; q < 3; ++q)
        for (const char* file : files[q]) {
            Network n;
            n.file           = file;
            n.path           = weights + "/" + file;
            UNet unet        = load(n.path);
            n.input_channels = unet.layout().input_channels;
            n.flops          = unet.layout().flops_per_pixel() * pixels;
            n.working        = unet.working_bytes(bench_height, bench_width, error);
            if (n.working == 0)
                fail(n.file + ": " + error);
            n.largest = largest_layer(unet.layout(), block);
            qualities[q].networks.push_back(std::move(n));
        }

    std::printf("# network_speed: %dx%d (1080p padded to %d), best of %d runs after a warm-up, "
                "channel block %d\n",
                bench_width, bench_height, mcdenoise::unet_alignment, runs, block);
    for (const int nthreads : thread_counts)
        measure(qualities, runs, nthreads, block);
    std::printf("\nLoad average (1, 5, 15 min): %s before, %s after.\n", load_before.c_str(),
                load_average().c_str());
    return 0;
}
