// render.cpp: the pixel loop. Worker threads take whole rows from a shared
// counter; every pixel is computed by one thread from its own random
// streams, so the output is bit-identical for any thread count.
#include "render.h"

#include "integrator.h"
#include "motion.h"

#include <atomic>
#include <chrono>
#include <thread>

namespace testrender {

namespace {

void store3(std::vector<float>& buf, size_t pixel, const Vec3& v)
{
    buf[pixel * 3 + 0] = float(v.x);
    buf[pixel * 3 + 1] = float(v.y);
    buf[pixel * 3 + 2] = float(v.z);
}

void add_passes(SamplePasses& sum, const SamplePasses& p)
{
    for (int lobe = 0; lobe < lobe_count; ++lobe) {
        sum.colour[lobe] += p.colour[lobe];
        sum.direct[lobe] += p.direct[lobe];
        sum.indirect[lobe] += p.indirect[lobe];
    }
    sum.emit += p.emit;
    sum.env += p.env;
}

void render_pixel(const Scene& scene, const ShotCameras& cameras, const RenderSettings& s,
                  uint64_t seed, int x, int y, RenderBuffers& out)
{
    const Camera& camera = cameras.current;
    const size_t pixel = size_t(y) * size_t(s.width) + size_t(x);
    Vec3 mean, m2, sum_a, sum_b, albedo, normal;  // Welford's running mean and M2
    double coverage = 0;
    SamplePasses pass_sums;
    for (int i = 0; i < s.spp; ++i) {
        SampleRng rng(seed, pixel, uint64_t(i));
        const double jx = rng.next(), jy = rng.next(), lu = rng.next(), lv = rng.next();
        const Ray ray = camera.generate(x + jx, y + jy, lu, lv);
        const PathResult r = trace_path(scene, ray, rng);
        const Vec3 delta = r.radiance - mean;
        mean += delta * (1.0 / (i + 1));
        m2 += delta * (r.radiance - mean);
        (i % 2 == 0 ? sum_a : sum_b) += r.radiance;
        albedo += r.albedo;
        normal += r.normal;
        coverage += r.alpha;
        if (s.passes)
            add_passes(pass_sums, r.passes);
    }
    const int n = s.spp;
    const int na = (n + 1) / 2, nb = n / 2;
    store3(out.beauty, pixel, mean);
    store3(out.variance, pixel, n > 1 ? m2 * (1.0 / (double(n - 1) * n)) : Vec3(0.0));
    store3(out.half_a, pixel, sum_a * (1.0 / na));
    store3(out.half_b, pixel, nb > 0 ? sum_b * (1.0 / nb) : Vec3(0.0));
    store3(out.albedo, pixel, albedo * (1.0 / n));
    store3(out.normal, pixel, normal * (1.0 / n));
    if (!out.alpha.empty())
        out.alpha[pixel] = float(coverage / n);
    if (s.passes)
        finish_passes(pass_sums, n, &out.passes[pixel * pass_channels]);
    const Ray center = camera.center_ray(x + 0.5, y + 0.5);
    const GeometryAovs g = trace_geometry(scene, center);
    out.depth[pixel] = g.depth;
    out.id[pixel] = float(g.id);
    out.reflid[pixel] = float(g.reflid);
    const MotionVector m = pixel_motion(scene, cameras, x + 0.5, y + 0.5, center, g);
    float* motion = &out.motion[pixel * 4];
    motion[0] = m.x;
    motion[1] = m.y;
    motion[2] = m.z;
    motion[3] = m.w;
}

}  // namespace

RenderBuffers render(const Scene& scene, const RenderSettings& s)
{
    const auto start = std::chrono::steady_clock::now();
    RenderBuffers out;
    out.width = s.width;
    out.height = s.height;
    const size_t npix = size_t(s.width) * size_t(s.height);
    for (std::vector<float>* b : { &out.beauty, &out.albedo, &out.normal, &out.variance,
                                   &out.half_a, &out.half_b })
        b->assign(npix * 3, 0.0f);
    for (std::vector<float>* b : { &out.depth, &out.id, &out.reflid })
        b->assign(npix, 0.0f);
    out.motion.assign(npix * 4, 0.0f);
    if (scene.transparent_film)
        out.alpha.assign(npix, 0.0f);
    if (s.passes)
        out.passes.assign(npix * pass_channels, 0.0f);

    const ShotCameras cameras(scene, s.width, s.height);
    const uint64_t seed = frame_seed(s.seed, s.frame);
    std::atomic<int> next_row { 0 };
    auto worker = [&]() {
        for (int y = next_row++; y < s.height; y = next_row++)
            for (int x = 0; x < s.width; ++x)
                render_pixel(scene, cameras, s, seed, x, y, out);
    };
    int nthreads = s.threads > 0 ? s.threads : int(std::thread::hardware_concurrency());
    nthreads = std::max(1, std::min(nthreads, s.height));
    std::vector<std::thread> pool;
    for (int t = 1; t < nthreads; ++t)
        pool.emplace_back(worker);
    worker();
    for (std::thread& t : pool)
        t.join();
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

}  // namespace testrender
