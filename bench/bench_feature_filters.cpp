// bench_feature_filters.cpp: the feature-guided filters (cross_bilateral,
// atrous, nlmeans, demodulate) on a real 1920x1080 testrender scene with
// every guide (its file named by MCD_BENCH_SCENE, as for
// bench_guided_filters), side by side with median 7 in the same run so the
// ratio survives a loaded machine.
#include <mcdenoise/mcdenoise.h>

#include "bench_scene.h"

#include <benchmark/benchmark.h>

namespace {

using OIIO::ImageBuf;

const testimg::Render& scene() { return benchimg::bench_scene("bench_feature_filters"); }

// Times `filter(scene, arg)` with arg = the benchmark's first argument and
// nthreads = its second (0: all cores).
template<class Filter>
void run(benchmark::State& state, Filter&& filter)
{
    scene();  // read the file before the clock starts
    const int arg = int(state.range(0)), nthreads = int(state.range(1));
    for (auto _ : state) {
        ImageBuf out = filter(scene(), arg, nthreads);
        if (out.has_error())
            state.SkipWithError(out.geterror().c_str());
        benchmark::DoNotOptimize(out.localpixels());
    }
    state.SetItemsProcessed(state.iterations() * scene().beauty.spec().image_pixels());
}

using namespace mcdenoise;
using testimg::Render;

void BM_median(benchmark::State& state)
{
    run(state, [](const Render& r, int size, int n) { return median(r.beauty, size, {}, n); });
}
BENCHMARK(BM_median)->Args({ 7, 0 })->Args({ 7, 1 })
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_cross_bilateral(benchmark::State& state)
{
    run(state, [](const Render& r, int size, int n) {
        return cross_bilateral(r.beauty, r.guides(), size, 2.0f, 0.0f, {}, {}, n);
    });
}
BENCHMARK(BM_cross_bilateral)->Args({ 7, 0 })->Args({ 7, 1 })
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_atrous(benchmark::State& state)
{
    run(state, [](const Render& r, int iterations, int n) {
        return atrous(r.beauty, r.guides(), iterations, 4.0f, {}, {}, n);
    });
}
BENCHMARK(BM_atrous)->Args({ 5, 0 })->Args({ 5, 1 })
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_nlmeans(benchmark::State& state)
{
    run(state, [](const Render& r, int radius, int n) {
        return nlmeans(r.beauty, r.guides(), radius, 1, 0.45f, {}, {}, n);
    });
}
BENCHMARK(BM_nlmeans)->Args({ 7, 0 })->Args({ 5, 0 })->Args({ 7, 1 })
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_demodulate(benchmark::State& state)
{
    run(state, [](const Render& r, int, int n) {
        return demodulate(r.beauty, r.albedo, 0.01f, {}, n);
    });
}
BENCHMARK(BM_demodulate)->Args({ 0, 0 })
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
