// uniform_windows.h: which windows fall entirely inside one object (one key):
// those take the simple filter's fast path. Found from runs of equal keys
// along rows, then along columns, so the cost does not depend on the window
// size.
#pragma once

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/parallel.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace mcdenoise {

/// For each pixel of `roi`, 1 if every pixel of its window of radius `r`
/// (clipped to `region`, which holds `roi` grown by `r`) carries its key,
/// else 0. `same(i, j)` says whether flat indices i and j of `region`
/// (row-major) carry the same key. Radii up to 127 (windows up to 255).
template<class Same>
std::vector<uint8_t> uniform_windows(const OIIO::ROI& region, const OIIO::ROI& roi, int r,
                                     int nthreads, Same&& same)
{
    constexpr int cap = 255;  // runs are counted up to this (> any radius + 1)
    const int w = region.width(), h = region.height();
    const OIIO::paropt threads(nthreads);
    // Runs of the center's key to the left and right (the pixel included).
    std::vector<uint8_t> left(size_t(w) * h), right(size_t(w) * h);
    OIIO::parallel_for(0, h, [&](int64_t y) {
        const size_t row = size_t(y) * w;
        left[row]        = 1;
        for (int x = 1; x < w; ++x)
            left[row + x] = same(row + x, row + x - 1) ? uint8_t(std::min(cap, left[row + x - 1] + 1)) : 1;
        right[row + w - 1] = 1;
        for (int x = w - 2; x >= 0; --x)
            right[row + x] = same(row + x, row + x + 1) ? uint8_t(std::min(cap, right[row + x + 1] + 1)) : 1;
    }, threads);
    // Whether the row segment of radius r around each pixel is all one key.
    // (Raw pointers throughout: byte stores would otherwise make the
    // compiler reload every vector's data pointer.)
    std::vector<uint8_t> whole(size_t(w) * h);
    {
        const uint8_t* L = left.data();
        const uint8_t* R = right.data();
        uint8_t* W       = whole.data();
        OIIO::parallel_for(0, h, [&](int64_t y) {
            const size_t row = size_t(y) * w;
            for (int x = 0; x < w; ++x)
                W[row + x] = L[row + x] > std::min(r, x) && R[row + x] > std::min(r, w - 1 - x);
        }, threads);
    }
    // Runs of rows, up then down, with whole segments and the center's key;
    // column blocks on separate threads. A pixel's window is uniform when both
    // runs reach r rows (or the region's edge).
    constexpr int block = 64;
    std::vector<uint8_t> up(size_t(w) * h);
    std::vector<uint8_t> uniform(size_t(roi.width()) * roi.height());
    const int rx0 = roi.xbegin - region.xbegin, rx1 = roi.xend - region.xbegin;
    const int ry0 = roi.ybegin - region.ybegin, ry1 = roi.yend - region.ybegin;
    OIIO::parallel_for(0, (w + block - 1) / block, [&](int64_t b) {
        const int x0 = int(b) * block, x1 = std::min(w, x0 + block);
        const uint8_t* W = whole.data();
        uint8_t* U       = up.data();
        uint8_t* out     = uniform.data();
        for (int y = 0; y < h; ++y)
            for (int x = x0; x < x1; ++x) {
                const size_t i = size_t(y) * w + x;
                U[i] = !W[i] ? 0 : y > 0 && same(i, i - w) ? uint8_t(std::min(cap, U[i - w] + 1)) : 1;
            }
        uint8_t down[block];
        for (int y = h - 1; y >= 0; --y) {
            const bool in_roi_row = y >= ry0 && y < ry1;
            for (int x = x0; x < x1; ++x) {
                const size_t i = size_t(y) * w + x;
                uint8_t& d     = down[x - x0];
                d = !W[i] ? 0 : y < h - 1 && same(i, i + w) ? uint8_t(std::min(cap, d + 1)) : 1;
                if (in_roi_row && x >= rx0 && x < rx1)
                    out[size_t(y - ry0) * roi.width() + size_t(x - rx0)]
                        = U[i] > std::min(r, y) && d > std::min(r, h - 1 - y);
            }
        }
    }, threads);
    return uniform;
}

}  // namespace mcdenoise
