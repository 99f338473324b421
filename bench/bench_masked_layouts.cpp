// bench_masked_layouts.cpp: why the masked values keep two layouts. On a
// 1920x1080 RGB float image, 1 thread: the cost of turning the interleaved
// pixels into channel planes (the planar layout the feature-guided sums
// read: `channel_planes`, and `sum_source` with the masked-value rule)
// against the separable means (mean and gaussian 3 and 7) that read the
// interleaved layout in place. Were the conversion cheap against the
// filter, the separable means could read planes too. Freed memory is kept
// for the next call, as mcdtool keeps it.
#include <mcdenoise/mcdenoise.h>

#include "bench_images.h"
#include "core/pixel_block.h"
#include "features/weighted_sums.h"
#include "freed_memory.h"

#include <benchmark/benchmark.h>

#include <stdexcept>

namespace {

using OIIO::ImageBuf;

const ImageBuf& frame()
{
    static const ImageBuf img = [] {
        // Repeated calls time the work, not page faults on planes glibc gave
        // back to the kernel since the last call (as in mcdtool).
        mcdtool::keep_freed_memory_for_the_next_frame();
        return benchimg::noisy_render();
    }();
    return img;
}

/// The frame's pixels as a block viewed in place, as the filters read them.
mcdenoise::PixelBlock frame_block()
{
    mcdenoise::PixelBlock block;
    if (!mcdenoise::load_block(frame(), frame().roi(), block))
        throw std::runtime_error(frame().geterror());
    return block;
}

/// Calls before the timing of each benchmark: the first few dozen still
/// grow the heap and fault fresh pages in (kept from then on, as in
/// mcdtool's later frames).
constexpr int warm_up_calls = 64;

/// Time `call`, after `warm_up_calls` untimed calls.
template<class Call>
void time_calls(benchmark::State& state, Call&& call)
{
    for (int i = 0; i < warm_up_calls; ++i)
        call();
    for (auto _ : state)
        call();
    state.SetItemsProcessed(state.iterations() * frame().spec().image_pixels());
}

void BM_channel_planes(benchmark::State& state)
{
    const mcdenoise::PixelBlock block = frame_block();
    time_calls(state, [&] {
        const mcdenoise::Planes<float> planes = mcdenoise::channel_planes(block, 1);
        benchmark::DoNotOptimize(planes.values.data());
    });
}

void BM_sum_source(benchmark::State& state)
{
    const mcdenoise::PixelBlock block = frame_block();
    time_calls(state, [&] {
        const mcdenoise::SumSource src
            = mcdenoise::sum_source(block, 0, block.nchannels, block.region, 1);
        benchmark::DoNotOptimize(src.values.data());
    });
}

void BM_with_finite_mask(benchmark::State& state)
{
    const mcdenoise::PixelBlock block = frame_block();
    time_calls(state, [&] {
        const mcdenoise::PixelBlock masked = mcdenoise::with_finite_mask(block, 1);
        benchmark::DoNotOptimize(masked.data);
    });
}

template<bool (*Filter)(ImageBuf&, const ImageBuf&, int, OIIO::ROI, int)>
void BM_filter(benchmark::State& state)
{
    time_calls(state, [&] {
        ImageBuf dst;
        if (!Filter(dst, frame(), int(state.range(0)), {}, 1))
            state.SkipWithError(dst.geterror().c_str());
        benchmark::DoNotOptimize(dst.localpixels());
    });
}

using Form = bool (*)(ImageBuf&, const ImageBuf&, int, OIIO::ROI, int);
constexpr Form mean_f     = mcdenoise::mean;
constexpr Form gaussian_f = mcdenoise::gaussian;

BENCHMARK(BM_channel_planes)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_sum_source)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_with_finite_mask)->Unit(benchmark::kMillisecond)->UseRealTime();
// Argument: the window size.
BENCHMARK(BM_filter<mean_f>)->Name("BM_mean")->Arg(3)->Arg(7)
    ->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_filter<gaussian_f>)->Name("BM_gaussian")->Arg(3)->Arg(7)
    ->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
