// operation.h: the steps every operation's bool and value forms share:
// checking the beauty and the ROI, where the result pixels go, and finishing
// `dst` once everything has succeeded.
#pragma once

#include "core/plane.h"

#include <OpenImageIO/imagebuf.h>

#include <atomic>
#include <cstdint>
#include <initializer_list>
#include <memory>

namespace mcdenoise {

/// Where an operation writes its pixels over `roi`: straight into `dst`
/// when it holds local float pixels no input shares, else a float buffer
/// that `finish_result` copies in.
class ResultPixels {
public:
    /// Pointer to channel `roi.chbegin` of pixel (x, y); the next channels
    /// follow contiguously.
    float* pixel(int x, int y) const
    {
        return m_base + interleaved_offset(roi, x, y, m_row_stride, m_pixel_stride);
    }

    /// Put the pixels of `roi` in a buffer owned by this object.
    void use_buffer(const OIIO::ROI& roi);

    /// Floats from one pixel to the next.
    std::ptrdiff_t pixel_stride() const { return m_pixel_stride; }

    OIIO::ROI roi;
    std::atomic<int64_t> empty_windows { 0 };  ///< windows with no finite value

private:
    friend bool begin_result(const char*, OIIO::ImageBuf&, const OIIO::ImageBuf&,
                             std::initializer_list<const OIIO::ImageBuf*>,
                             const OIIO::ROI&, ResultPixels&);
    friend bool finish_result(const char*, OIIO::ImageBuf&, ResultPixels&);
    float* m_base                 = nullptr;
    std::ptrdiff_t m_pixel_stride = 0;  // in floats
    std::ptrdiff_t m_row_stride   = 0;  // in floats
    std::unique_ptr<float[]> m_buffer;  // when not writing into dst
};

/// Settle `roi` for an operation on `beauty`: the default is the beauty's
/// data window and all channels; an explicit ROI must lie inside the data
/// window. On failure, sets `dst`'s error prefixed with `op` and returns
/// false.
bool resolve_roi(const char* op, OIIO::ImageBuf& dst, const OIIO::ImageBuf& beauty,
                 OIIO::ROI& roi);

/// Resolve the ROI and check a window size: the checks every window filter
/// makes before it reads a pixel.
bool check_window_op(const char* op, OIIO::ImageBuf& dst, const OIIO::ImageBuf& beauty,
                     int size, OIIO::ROI& roi);

/// Allocate `dst` if needed (float pixels covering `roi`, like `beauty`
/// otherwise) and point `result` at where the pixels go. Call only once
/// every input has been checked and read: from here on `dst` changes.
/// `inputs` are every image the operation reads (to detect in-place use);
/// null entries (absent optional guides) are skipped.
bool begin_result(const char* op, OIIO::ImageBuf& dst, const OIIO::ImageBuf& beauty,
                  std::initializer_list<const OIIO::ImageBuf*> inputs,
                  const OIIO::ROI& roi, ResultPixels& result);

/// Copy buffered pixels into `dst` and record the count of empty windows in
/// the `dst` attribute `mcdenoise:empty_windows`.
bool finish_result(const char* op, OIIO::ImageBuf& dst, ResultPixels& result);

/// The value form of an operation: run the bool form `run(dst)` on a new
/// image and return it, with an error set if it failed.
template<class BoolForm>
OIIO::ImageBuf value_form(BoolForm&& run)
{
    OIIO::ImageBuf dst;
    if (!run(dst) && !dst.has_error())
        dst.errorfmt("mcdenoise: operation failed");
    return dst;
}

}  // namespace mcdenoise
