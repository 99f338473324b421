// bench_guided_filters.cpp: the guided filters on a real testrender scene at
// 1920x1080 (its file named by MCD_BENCH_SCENE, made by bench/speed_table),
// side by side with the simple filters of the same size in the same run.
#include <mcdenoise/mcdenoise.h>

#include "bench_scene.h"

#include <benchmark/benchmark.h>

namespace {

using OIIO::ImageBuf;

const testimg::Render& scene() { return benchimg::bench_scene("bench_guided_filters"); }

template<class Filter>
void run(benchmark::State& state, Filter&& filter)
{
    scene();  // read the file before the clock starts
    const int size = int(state.range(0));
    for (auto _ : state) {
        ImageBuf out = filter(scene(), size);
        if (out.has_error())
            state.SkipWithError(out.geterror().c_str());
        benchmark::DoNotOptimize(out.localpixels());
    }
    state.SetItemsProcessed(state.iterations() * scene().beauty.spec().image_pixels());
}

#define MCD_BENCH(name, expr)                                                             \
    void BM_##name(benchmark::State& state)                                              \
    {                                                                                     \
        run(state, [](const testimg::Render& r, int s) { return expr; });                 \
    }                                                                                     \
    BENCHMARK(BM_##name)->Arg(3)->Arg(7)->Unit(benchmark::kMillisecond)->UseRealTime()

using namespace mcdenoise;
MCD_BENCH(median, median(r.beauty, s));
MCD_BENCH(object_median, object_median(r.beauty, r.object_id, s));
MCD_BENCH(brdf_median, brdf_median(r.beauty, r.object_id, r.reflect_id, s));
MCD_BENCH(mean, mean(r.beauty, s));
MCD_BENCH(object_mean, object_mean(r.beauty, r.object_id, s));
MCD_BENCH(brdf_mean, brdf_mean(r.beauty, r.object_id, r.reflect_id, s));
MCD_BENCH(normal_mean, normal_mean(r.beauty, r.object_id, r.normal, s));
MCD_BENCH(gaussian, gaussian(r.beauty, s));
MCD_BENCH(object_gaussian, object_gaussian(r.beauty, r.object_id, s));
MCD_BENCH(brdf_gaussian, brdf_gaussian(r.beauty, r.object_id, r.reflect_id, s));
MCD_BENCH(normal_gaussian, normal_gaussian(r.beauty, r.object_id, r.normal, s));

/// The scene's beauty on one curved object: a sphere-like normal field in
/// which no two neighbours are alike (smooth-shaded meshes in production
/// renders), so no window takes the fast path.
const testimg::Render& curved_scene()
{
    static const testimg::Render curved = [] {
        testimg::Render r;
        r.beauty.copy(scene().beauty);
        const OIIO::ROI roi = r.beauty.roi();
        OIIO::ROI plane = roi;
        plane.chbegin   = 0;
        plane.chend     = 1;
        r.object_id.reset(OIIO::ImageSpec(plane, OIIO::TypeDesc::FLOAT));  // all zero
        plane.chend = 3;
        r.normal.reset(OIIO::ImageSpec(plane, OIIO::TypeDesc::FLOAT));
        const float cx = float(roi.xbegin + roi.xend) / 2, cy = float(roi.ybegin + roi.yend) / 2;
        const float radius = float(roi.width());
        for (OIIO::ImageBuf::Iterator<float> it(r.normal); !it.done(); ++it) {
            it[0] = (float(it.x()) - cx) / radius;
            it[1] = (float(it.y()) - cy) / radius;
            it[2] = 1.0f;
        }
        return r;
    }();
    return curved;
}

void BM_normal_mean_curved(benchmark::State& state)
{
    curved_scene();  // made before the clock starts
    run(state, [](const testimg::Render&, int s) {
        const testimg::Render& r = curved_scene();
        return normal_mean(r.beauty, r.object_id, r.normal, s);
    });
}
BENCHMARK(BM_normal_mean_curved)->Arg(3)->Arg(7)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_object_mean_19(benchmark::State& state)
{
    run(state, [](const testimg::Render& r, int) { return object_mean(r.beauty, r.object_id, 19); });
}
BENCHMARK(BM_object_mean_19)->Arg(19)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_dof_10_levels(benchmark::State& state)
{
    run(state, [](const testimg::Render& r, int) {
        return dof(r.beauty, r.object_id, r.depth, 10, 0);
    });
}
BENCHMARK(BM_dof_10_levels)->Arg(10)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
