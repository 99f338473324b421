// bench_simple_filters.cpp: mean, median and gaussian on a 1920x1080 RGB
// float image, side by side with OpenImageIO's nearest operations and with a
// plain copy of the same pixels (the memory-bandwidth floor), in one run.
#include <mcdenoise/mcdenoise.h>

#include "bench_images.h"

#include <OpenImageIO/imagebufalgo.h>
#include <benchmark/benchmark.h>

namespace {

using OIIO::ImageBuf;

const ImageBuf& frame()
{
    static const ImageBuf img = benchimg::noisy_render();
    return img;
}

void report_pixels(benchmark::State& state)
{
    state.SetItemsProcessed(state.iterations() * frame().spec().image_pixels());
}

void BM_copy(benchmark::State& state)
{
    for (auto _ : state) {
        ImageBuf dst;
        OIIO::ImageBufAlgo::copy(dst, frame(), OIIO::TypeDesc::FLOAT, {}, int(state.range(0)));
        benchmark::DoNotOptimize(dst.localpixels());
    }
    report_pixels(state);
}

template<bool (*Filter)(ImageBuf&, const ImageBuf&, int, OIIO::ROI, int)>
void BM_filter(benchmark::State& state)
{
    for (auto _ : state) {
        ImageBuf dst;
        if (!Filter(dst, frame(), int(state.range(0)), {}, int(state.range(1))))
            state.SkipWithError(dst.geterror().c_str());
        benchmark::DoNotOptimize(dst.localpixels());
    }
    report_pixels(state);
}

void BM_oiio_median_filter(benchmark::State& state)
{
    const int size = int(state.range(0));
    for (auto _ : state) {
        ImageBuf dst;
        OIIO::ImageBufAlgo::median_filter(dst, frame(), size, size, {}, int(state.range(1)));
        benchmark::DoNotOptimize(dst.localpixels());
    }
    report_pixels(state);
}

void BM_oiio_convolve_gaussian(benchmark::State& state)
{
    const float size = float(state.range(0));
    const ImageBuf kernel = OIIO::ImageBufAlgo::make_kernel("gaussian", size, size);
    for (auto _ : state) {
        ImageBuf dst;
        OIIO::ImageBufAlgo::convolve(dst, frame(), kernel, true, {}, int(state.range(1)));
        benchmark::DoNotOptimize(dst.localpixels());
    }
    report_pixels(state);
}

using Form = bool (*)(ImageBuf&, const ImageBuf&, int, OIIO::ROI, int);
constexpr Form mean_f     = mcdenoise::mean;
constexpr Form median_f   = mcdenoise::median;
constexpr Form gaussian_f = mcdenoise::gaussian;

// Arguments: {window size, threads (0 = all cores)}.
BENCHMARK(BM_copy)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_filter<mean_f>)->Name("BM_mean")
    ->Args({ 3, 0 })->Args({ 7, 0 })->Args({ 31, 0 })->Args({ 3, 1 })->Args({ 7, 1 })
    ->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_filter<median_f>)->Name("BM_median")
    ->Args({ 3, 0 })->Args({ 7, 0 })->Args({ 3, 1 })->Args({ 7, 1 })
    ->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_filter<gaussian_f>)->Name("BM_gaussian")
    ->Args({ 3, 0 })->Args({ 7, 0 })->Args({ 3, 1 })->Args({ 7, 1 })
    ->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_oiio_median_filter)->Args({ 7, 0 })->Iterations(1)
    ->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_oiio_convolve_gaussian)->Args({ 7, 0 })->Iterations(2)
    ->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
