// simple.cpp: the report's simple filters: mean, median and gaussian.
#include <mcdenoise/simple.h>

#include "median_walker.h"
#include "operation.h"
#include "separable_mean.h"

#include <OpenImageIO/imagebufalgo_util.h>

namespace mcdenoise {

using OIIO::ImageBuf;
using OIIO::ROI;

namespace {

// Every neighbour is viable: the simple filters' rule.
struct AllViable {
    bool uniform(int, int) const { return true; }
    bool viable(int, int, int, int) const { return true; }
};

bool separable_filter(const char* op, ImageBuf& dst, const ImageBuf& beauty,
                      int size, Kernel1D (*make_kernel)(int), ROI roi, int nthreads)
{
    SeparableSource source;
    ResultPixels result;
    if (!check_window_op(op, dst, beauty, size, roi)
        || !load_separable_source(op, dst, beauty, roi, make_kernel(size), nthreads, source)
        || !begin_result(op, dst, beauty, { &beauty }, roi, result))
        return false;
    OIIO::ImageBufAlgo::parallel_image(roi, nthreads, [&](ROI strip) {
        separable_mean_strip(source, strip, result);
    });
    return finish_result(op, dst, result);
}

}  // namespace

bool mean(ImageBuf& dst, const ImageBuf& beauty, int size, ROI roi, int nthreads)
{
    return separable_filter("mean", dst, beauty, size, box_kernel, roi, nthreads);
}

ImageBuf mean(const ImageBuf& beauty, int size, ROI roi, int nthreads)
{
    return value_form([&](ImageBuf& dst) { return mean(dst, beauty, size, roi, nthreads); });
}

bool gaussian(ImageBuf& dst, const ImageBuf& beauty, int size, ROI roi, int nthreads)
{
    return separable_filter("gaussian", dst, beauty, size, binomial_kernel, roi, nthreads);
}

ImageBuf gaussian(const ImageBuf& beauty, int size, ROI roi, int nthreads)
{
    return value_form(
        [&](ImageBuf& dst) { return gaussian(dst, beauty, size, roi, nthreads); });
}

bool median(ImageBuf& dst, const ImageBuf& beauty, int size, ROI roi, int nthreads)
{
    MedianSource source;
    ResultPixels result;
    if (!check_window_op("median", dst, beauty, size, roi)
        || !load_median_source("median", dst, beauty, roi, size, nthreads, source)
        || !begin_result("median", dst, beauty, { &beauty }, roi, result))
        return false;
    OIIO::ImageBufAlgo::parallel_image(roi, nthreads, [&](ROI strip) {
        median_strip(source, AllViable(), strip, result);
    });
    return finish_result("median", dst, result);
}

ImageBuf median(const ImageBuf& beauty, int size, ROI roi, int nthreads)
{
    return value_form([&](ImageBuf& dst) { return median(dst, beauty, size, roi, nthreads); });
}

}  // namespace mcdenoise
