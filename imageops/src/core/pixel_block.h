// pixel_block.h: contiguous float pixels of one rectangle of an image, the
// form every hot loop reads. Converted once from any pixel type, or viewed in
// place when the image already holds local float pixels.
#pragma once

#include "core/plane.h"

#include <OpenImageIO/imagebuf.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <vector>

namespace mcdenoise {

/// Float pixels of `region` (x, y and its channel range), channels
/// interleaved, rows `row_stride` floats apart.
struct PixelBlock {
    PixelBlock()                  = default;
    PixelBlock(PixelBlock&&)      = default;
    PixelBlock(const PixelBlock&) = delete;  // `data` may point into `owned`
    PixelBlock& operator=(PixelBlock&&) = default;

    OIIO::ROI region;
    int nchannels         = 0;
    std::ptrdiff_t row_stride = 0;
    const float* data     = nullptr;
    std::vector<float> owned;

    /// Pointer to channel 0 of pixel (x, y), which must lie in `region`.
    const float* pixel(int x, int y) const
    {
        return data + interleaved_offset(region, x, y, row_stride, nchannels);
    }
    /// Pointer to the first pixel of row `y`.
    const float* row(int y) const { return pixel(region.xbegin, y); }
    /// Row `y` of a block that owns its pixels, for writing them.
    float* owned_row(int y)
    {
        return owned.data() + interleaved_offset(region, region.xbegin, y, row_stride, nchannels);
    }
    int width() const { return region.width(); }
    int height() const { return region.height(); }
};

/// Fill `block` with the pixels of `img` in `region` (whose channel range
/// selects the channels). Views the image's memory when it already holds
/// local float pixels with exactly those channels; converts otherwise.
/// Returns false, with the image's error, if the pixels cannot be read.
bool load_block(const OIIO::ImageBuf& img, OIIO::ROI region, PixelBlock& block);

/// `load_block` for an operation's beauty: on failure sets `dst`'s error,
/// prefixed with `op`, and returns false.
bool read_beauty(const char* op, OIIO::ImageBuf& dst, const OIIO::ImageBuf& beauty,
                 const OIIO::ROI& region, PixelBlock& block);

/// The largest magnitude a window sum takes from a finite value: larger ones
/// (a broken sample, far beyond any radiance) are clamped to it, so a sum of
/// up to 2^27 of them with weights of at most 1 still fits in a float and a
/// mean of finite values stays finite. Medians see the values unclamped.
constexpr float max_summed_magnitude = 0x1p100f;

/// What a window sum takes from `v`: `v` clamped to +-max_summed_magnitude,
/// or 0 when it is NaN or infinite.
inline float summable(float v)
{
    return std::isfinite(v) ? std::clamp(v, -max_summed_magnitude, max_summed_magnitude) : 0.0f;
}

/// The weight a masked sum gives `v`: 1 when it is finite, 0 when it is NaN
/// or infinite.
inline float finite_weight(float v)
{
    return std::isfinite(v) ? 1.0f : 0.0f;
}

/// The one masked-value rule, the producer of both masked layouts (the
/// interleaved `with_finite_mask`, the planar `sum_source`): for the `n`
/// values `in[i * in_step]`, the value a masked sum takes (`summable`) into
/// `values[i * out_step]` and its weight (`finite_weight`) into
/// `weights[i * out_step]` (when `weights` is null, the weights are only
/// looked at). Returns true if some weight is 0.
inline bool masked_values(const float* in, std::ptrdiff_t in_step, int n, float* values,
                          float* weights, std::ptrdiff_t out_step)
{
    float least = 1.0f;
    for (int i = 0; i < n; ++i) {
        const float v = in[i * in_step], w = finite_weight(v);
        values[i * out_step] = summable(v);
        if (weights)
            weights[i * out_step] = w;
        least = std::min(least, w);
    }
    return least == 0.0f;
}

/// A channel's weighted mean over the finite values of its window: `num /
/// den`, the weighted sum of those values over the weights that contributed,
/// or 0 when none did (an empty window, counted in `empty`). The one rule
/// every masked mean ends with (the separable mean's rows, RowMeans, divide
/// by multiplying with the weights' reciprocal: the same rule, their own
/// rounding).
template<class Sum, class Count>
inline float masked_mean(Sum num, Sum den, Count& empty)
{
    const bool any = den > Sum(0);
    empty += !any;
    return any ? float(num / den) : 0.0f;
}

/// True if any value of `block` is NaN or infinite.
bool has_nonfinite(const PixelBlock& block, int nthreads);

/// True if any value of `block` is NaN, infinite or beyond
/// max_summed_magnitude: sums of it must read `with_finite_mask`.
bool needs_finite_mask(const PixelBlock& block, int nthreads);

/// A copy of `src` with twice the channels: the masked values of each
/// pixel (`masked_values`), its values as a sum takes them, then their
/// weights. Summing both halves with the same weights gives a masked
/// numerator and the weights that contributed.
PixelBlock with_finite_mask(const PixelBlock& src, int nthreads);

/// A block like `src` holding 1 where its value is non-finite, 0 elsewhere.
PixelBlock nonfinite_indicator(const PixelBlock& src, int nthreads);

/// Each channel of `src` as a plane over its region.
Planes<float> channel_planes(const PixelBlock& src, int nthreads);

}  // namespace mcdenoise
