// window.h: the geometry of square filter windows: sizes, radii, clipping to
// the data window, and the fixed restart points of sliding sums.
#pragma once

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo_util.h>

#include <algorithm>
#include <string>

namespace mcdenoise {

/// A half-open range of pixel coordinates [begin, end).
struct Span {
    int begin = 0;
    int end   = 0;
    int size() const { return end - begin; }
};

/// The window of radius `radius` around `center`, clipped to [lo, hi).
inline Span clip_window(int center, int radius, int lo, int hi)
{
    return { std::max(lo, center - radius), std::min(hi, center + radius + 1) };
}

/// Empty if `size` is a valid window side (odd, 1..max_window_size), else
/// the message explaining why not.
std::string check_window_size(int size);

/// `roi` grown by `radius` on each side in x and y, then clipped to `bounds`
/// (the channel range is `roi`'s).
OIIO::ROI grow_and_clip(const OIIO::ROI& roi, int radius, const OIIO::ROI& bounds);

/// Sliding sums restart from scratch at fixed points so that a pixel's sum
/// never depends on where a thread or an ROI began: every `interval` pixels
/// from the data window's `origin`. The interval grows with the radius to
/// keep the restart cost a small fraction of the sweep.
int restart_interval(int radius);

/// The last restart point at or before `x`.
int restart_at_or_before(int x, int origin, int interval);

/// Run `row_fn(y)` for every row y of `rows` (its x range sets the work per
/// row), rows split among `nthreads` threads like any image operation.
template<class RowFn>
void parallel_rows(const OIIO::ROI& rows, int nthreads, RowFn&& row_fn)
{
    OIIO::ROI one = rows;
    one.chbegin   = 0;
    one.chend     = 1;
    OIIO::ImageBufAlgo::parallel_image(one, nthreads, [&](OIIO::ROI strip) {
        for (int y = strip.ybegin; y < strip.yend; ++y)
            row_fn(y);
    });
}

}  // namespace mcdenoise
