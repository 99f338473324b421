// offset_walk.h: the one walk over window offsets of the feature-guided
// filters (cross_bilateral, atrous, nlmeans, clamp_fireflies). They filter a
// run of pixels of one row at a time, one neighbour offset (dx, dy) at a
// time, so every pixel's neighbour at that offset sits in one contiguous
// row; the walk clips each offset to the pixels whose neighbour lies
// inside the image and skips offsets that leave no such pixel.
#pragma once

#include <OpenImageIO/imageio.h>

#include <algorithm>

namespace mcdenoise {

/// One neighbour offset of a run of pixels [x0, x0 + n) of row y: the
/// pixels x0 + i, i in [i0, i1), have their neighbour (x0 + i + dx, y + dy)
/// inside the bounds; `kx`, `ky` are the offset in taps (dx = kx * step).
struct Offset {
    int kx, ky;
    int dx, dy;
    int i0, i1;

    /// The pixel itself: its weight is the filter's centre weight, not a
    /// comparison with itself.
    bool centre() const { return dx == 0 && dy == 0; }
    /// How many pixels of the run have this neighbour.
    int count() const { return i1 - i0; }
    /// The column of the first neighbour, of pixel x0 + i0.
    int first_neighbour(int x0) const { return x0 + i0 + dx; }
};

/// The offset (kx * step, ky * step) of the run [x0, x0 + n) clipped to
/// the columns of `bounds` (an empty span when no neighbour is inside).
inline Offset clip_offset(int kx, int ky, int step, int x0, int n, const OIIO::ROI& bounds)
{
    const int dx = kx * step, dy = ky * step;
    return { kx, ky, dx, dy, std::max(0, bounds.xbegin - dx - x0),
             std::min(n, bounds.xend - dx - x0) };
}

/// Calls `fn(const Offset&)` for the offsets (kx * step, ky * step), kx and
/// ky in [-taps, taps], row by row, of the run [x0, x0 + n) of row y,
/// clipped to `bounds`: offsets whose row lies outside `bounds`, or whose
/// span is empty, are skipped.
template<class Fn>
void for_each_offset(int y, int x0, int n, int taps, int step, const OIIO::ROI& bounds, Fn&& fn)
{
    for (int ky = -taps; ky <= taps; ++ky) {
        const int qy = y + ky * step;
        if (qy < bounds.ybegin || qy >= bounds.yend)
            continue;
        for (int kx = -taps; kx <= taps; ++kx) {
            const Offset o = clip_offset(kx, ky, step, x0, n, bounds);
            if (o.i0 < o.i1)
                fn(o);
        }
    }
}

}  // namespace mcdenoise
