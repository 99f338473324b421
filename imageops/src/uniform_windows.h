// uniform_windows.h: which windows fall entirely inside one object (one key):
// those take the simple filter's fast path. Found from runs of equal keys
// along rows and columns, so the cost does not depend on the window size.
#pragma once

#include "guides.h"

#include <OpenImageIO/parallel.h>

#include <cstdint>
#include <vector>

namespace mcdenoise {

/// Runs of equal keys through each pixel of `region`: how many pixels to
/// the left and right (each counting the pixel itself) carry its key.
struct KeyRuns {
    OIIO::ROI region;
    std::vector<int32_t> left, right;
};

/// The runs of a key given by `same(i, j)`: whether flat indices i and j of
/// `region` (row-major) carry the same key.
template<class Same>
KeyRuns key_runs(const OIIO::ROI& region, int nthreads, Same&& same)
{
    KeyRuns runs;
    runs.region = region;
    const int w = region.width(), h = region.height();
    runs.left.resize(size_t(w) * h);
    runs.right.resize(size_t(w) * h);
    OIIO::parallel_for(0, h, [&](int64_t y) {
        const size_t row = size_t(y) * w;
        for (int x = 0; x < w; ++x)
            runs.left[row + x] = x > 0 && same(row + x, row + x - 1) ? runs.left[row + x - 1] + 1 : 1;
        for (int x = w - 1; x >= 0; --x)
            runs.right[row + x] = x < w - 1 && same(row + x, row + x + 1) ? runs.right[row + x + 1] + 1
                                                                         : 1;
    }, OIIO::paropt(nthreads));
    return runs;
}

/// For each pixel of `roi`, 1 if every pixel of its window of radius `r`
/// (clipped to the runs' region) carries its key, else 0. `same` is the key
/// equality `key_runs` was given.
template<class Same>
std::vector<uint8_t> uniform_windows(const KeyRuns& runs, const OIIO::ROI& roi, int r,
                                     int nthreads, Same&& same)
{
    const OIIO::ROI& reg = runs.region;
    const int w = reg.width(), h = reg.height();
    const OIIO::paropt threads(nthreads);
    // Rows whose segment around x is all one key.
    std::vector<uint8_t> row_ok(size_t(w) * h);
    OIIO::parallel_for(0, h, [&](int64_t y) {
        for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y) * w + x;
            row_ok[i] = runs.left[i] > std::min(r, x) && runs.right[i] > std::min(r, w - 1 - x);
        }
    }, threads);
    // Up and down: consecutive rows with whole segments and the same key,
    // column blocks on separate threads.
    constexpr int block = 64;
    std::vector<int32_t> up(size_t(w) * h), down(size_t(w) * h);
    OIIO::parallel_for(0, (w + block - 1) / block, [&](int64_t b) {
        const int x0 = int(b) * block, x1 = std::min(w, x0 + block);
        for (int y = 0; y < h; ++y)
            for (int x = x0; x < x1; ++x) {
                const size_t i = size_t(y) * w + x;
                up[i] = !row_ok[i] ? 0 : (y > 0 && same(i, i - w) ? up[i - w] + 1 : 1);
            }
        for (int y = h - 1; y >= 0; --y)
            for (int x = x0; x < x1; ++x) {
                const size_t i = size_t(y) * w + x;
                down[i] = !row_ok[i] ? 0 : (y < h - 1 && same(i, i + w) ? down[i + w] + 1 : 1);
            }
    }, threads);
    std::vector<uint8_t> uniform(size_t(roi.width()) * roi.height());
    OIIO::parallel_for(roi.ybegin, roi.yend, [&](int64_t y) {
        for (int x = roi.xbegin; x < roi.xend; ++x) {
            const int ry = int(y) - reg.ybegin;
            const size_t i = size_t(ry) * w + size_t(x - reg.xbegin);
            uniform[size_t(y - roi.ybegin) * roi.width() + size_t(x - roi.xbegin)]
                = up[i] > std::min(r, ry) && down[i] > std::min(r, h - 1 - ry);
        }
    }, threads);
    return uniform;
}

}  // namespace mcdenoise
