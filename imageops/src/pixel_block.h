// pixel_block.h: contiguous float pixels of one rectangle of an image, the
// form every hot loop reads. Converted once from any pixel type, or viewed in
// place when the image already holds local float pixels.
#pragma once

#include <OpenImageIO/imagebuf.h>

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
        return data + (y - region.ybegin) * row_stride
               + std::ptrdiff_t(x - region.xbegin) * nchannels;
    }
    /// Pointer to the first pixel of row `y`.
    const float* row(int y) const { return pixel(region.xbegin, y); }
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

/// True if any value of `block` is NaN or infinite.
bool has_nonfinite(const PixelBlock& block, int nthreads);

/// A copy of `src` with twice the channels: each finite value as it is (0 in
/// place of a non-finite one), then for each channel 1 where the value is
/// finite and 0 where not. Summing both halves with the same weights gives
/// a masked numerator and the weights that contributed.
PixelBlock with_finite_mask(const PixelBlock& src, int nthreads);

/// A block like `src` holding 1 where its value is non-finite, 0 elsewhere.
PixelBlock nonfinite_indicator(const PixelBlock& src, int nthreads);

/// Each channel of `src` as a contiguous plane (row stride = width).
std::vector<std::unique_ptr<float[]>> channel_planes(const PixelBlock& src, int nthreads);

}  // namespace mcdenoise
