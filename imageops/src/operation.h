// operation.h: the steps every operation's bool and value forms share:
// checking the beauty and the ROI, the float result buffer the filters fill,
// and writing it into `dst` only once everything has succeeded.
#pragma once

#include <OpenImageIO/imagebuf.h>

#include <atomic>
#include <cstdint>
#include <vector>

namespace mcdenoise {

/// The finished pixels of an operation over `roi`, channels interleaved.
struct ResultPixels {
    explicit ResultPixels(const OIIO::ROI& roi);

    /// Pointer to channel `roi.chbegin` of pixel (x, y).
    float* pixel(int x, int y)
    {
        return data.data()
               + (size_t(y - roi.ybegin) * roi.width() + size_t(x - roi.xbegin))
                     * roi.nchannels();
    }

    OIIO::ROI roi;
    std::vector<float> data;
    std::atomic<int64_t> empty_windows { 0 };  ///< windows with no finite value
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

/// Allocate `dst` if needed (float pixels covering the ROI) and copy the
/// result in; record the count of empty windows in the `dst` attribute
/// `mcdenoise:empty_windows`.
bool write_result(const char* op, OIIO::ImageBuf& dst, const OIIO::ImageBuf& beauty,
                  const ResultPixels& result);

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
