// simple.cpp: the report's simple filters: mean, median and gaussian, the
// window filters whose every neighbour is viable.
#include <mcdenoise/simple.h>

#include "walkers/window_filter.h"

namespace mcdenoise {

using OIIO::ImageBuf;
using OIIO::ROI;

namespace {

bool simple_filter(const char* op, Reduction reduction, ImageBuf& dst,
                   const ImageBuf& beauty, int size, ROI roi, int nthreads)
{
    return check_window_op(op, dst, beauty, size, roi)
           && run_window_filter(op, reduction, dst, beauty, { &beauty }, size, AllViable(),
                                roi, nthreads);
}

}  // namespace

bool mean(ImageBuf& dst, const ImageBuf& beauty, int size, ROI roi, int nthreads)
{
    return simple_filter("mean", Reduction::box_mean, dst, beauty, size, roi, nthreads);
}

ImageBuf mean(const ImageBuf& beauty, int size, ROI roi, int nthreads)
{
    return value_form([&](ImageBuf& dst) { return mean(dst, beauty, size, roi, nthreads); });
}

bool gaussian(ImageBuf& dst, const ImageBuf& beauty, int size, ROI roi, int nthreads)
{
    return simple_filter("gaussian", Reduction::binomial_mean, dst, beauty, size, roi,
                         nthreads);
}

ImageBuf gaussian(const ImageBuf& beauty, int size, ROI roi, int nthreads)
{
    return value_form(
        [&](ImageBuf& dst) { return gaussian(dst, beauty, size, roi, nthreads); });
}

bool median(ImageBuf& dst, const ImageBuf& beauty, int size, ROI roi, int nthreads)
{
    return simple_filter("median", Reduction::median, dst, beauty, size, roi, nthreads);
}

ImageBuf median(const ImageBuf& beauty, int size, ROI roi, int nthreads)
{
    return value_form([&](ImageBuf& dst) { return median(dst, beauty, size, roi, nthreads); });
}

}  // namespace mcdenoise
