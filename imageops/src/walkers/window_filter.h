// window_filter.h: runs a window filter from its rule: reads the beauty once
// in the form the reduction needs, allocates the result only after every
// input has been read, walks the ROI on all threads, and finishes `dst`.
#pragma once

#include "core/operation.h"
#include "walkers/guided_strip.h"
#include "walkers/median_walker.h"

#include <OpenImageIO/imagebufalgo_util.h>

#include <initializer_list>

namespace mcdenoise {

/// How a window's viable values become one value.
enum class Reduction { box_mean, binomial_mean, median };

/// Every neighbour is viable with weight 1: the simple filters' rule. Every
/// rule provides `uniform_row(y, xs, out)`: out[x - xs.begin] is 1 where
/// (x, y)'s window is wholly viable with guide weight 1, else 0.
struct AllViable {
    void uniform_row(int, Span xs, uint8_t* out) const { std::fill_n(out, xs.size(), uint8_t(1)); }
    void row_weights(int, int, int, Span xs, float* w) const { std::fill_n(w, xs.size(), 1.0f); }
};

/// Filter `roi` of `beauty` (already checked, like every guide) into `dst`
/// with window side `size`, reducing the viable neighbours that `rule`
/// picks by `reduction`. `inputs` are every image read (for in-place use).
template<class Rule>
bool run_window_filter(const char* op, Reduction reduction, OIIO::ImageBuf& dst,
                       const OIIO::ImageBuf& beauty,
                       std::initializer_list<const OIIO::ImageBuf*> inputs, int size,
                       const Rule& rule, const OIIO::ROI& roi, int nthreads)
{
    ResultPixels result;
    if (reduction == Reduction::median) {
        MedianSource source;
        if (!load_median_source(op, dst, beauty, roi, size, nthreads, source)
            || !begin_result(op, dst, beauty, inputs, roi, result))
            return false;
        OIIO::ImageBufAlgo::parallel_image(roi, nthreads, [&](OIIO::ROI strip) {
            median_strip(source, rule, strip, result);
        });
        return finish_result(op, dst, result);
    }
    SeparableSource source;
    Kernel1D kernel = reduction == Reduction::box_mean ? box_kernel(size)
                                                       : binomial_kernel(size);
    if (!load_separable_source(op, dst, beauty, roi, std::move(kernel), nthreads, source)
        || !begin_result(op, dst, beauty, inputs, roi, result))
        return false;
    OIIO::ImageBufAlgo::parallel_image(roi, nthreads, [&](OIIO::ROI strip) {
        if constexpr (std::is_same_v<Rule, AllViable>)
            separable_mean_strip(source, strip, result);
        else
            guided_mean_strip(source, rule, strip, result);
    });
    return finish_result(op, dst, result);
}

}  // namespace mcdenoise
