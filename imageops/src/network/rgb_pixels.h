// rgb_pixels.h: how the network's pipeline is given an image: a pointer to
// interleaved float pixels whose first three values are R, G, B, with a
// pixel stride and a row stride in floats (the layout of an ImageBuf's
// local pixels or of any RGB/RGBA buffer). Read by the autoexposure
// (autoexposure.h) and the tile I/O (tile_io.h), written by the latter.
#pragma once

#include <cstddef>

namespace mcdenoise {

/// An RGB image of `width` x `height` interleaved float pixels; `T` is
/// `const float` for an image read, `float` for one written.
template<class T>
struct RgbPixels {
    /// The first value (R) of pixel (0, 0).
    T* data    = nullptr;
    int width  = 0;
    int height = 0;
    /// Floats from one pixel to the next along a row; at least 3.
    std::ptrdiff_t pixel_stride = 3;
    /// Floats from one row to the next; at least `width * pixel_stride`
    /// less the unused values of the last pixel (rows may not overlap).
    std::ptrdiff_t row_stride = 0;

    /// The first value of pixel (x, y).
    T* pixel(int x, int y) const { return data + y * row_stride + x * pixel_stride; }
    /// Whether the image can be read or written: data set, a positive
    /// size, a pixel stride of at least 3 and rows that do not overlap.
    bool valid() const
    {
        return data != nullptr && width > 0 && height > 0 && pixel_stride >= 3
               && row_stride >= (width - 1) * pixel_stride + 3;
    }
};

/// An image the pipeline reads.
using RgbIn = RgbPixels<const float>;
/// An image the pipeline writes.
using RgbOut = RgbPixels<float>;

}  // namespace mcdenoise
