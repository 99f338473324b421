// dot_weighted_mean.h: weighted means whose guide weight is the dot product
// of the center's and the neighbour's vectors (the normal weight on smooth
// surfaces, where every dot in the window is positive). The weighted sum is
// then linear in the center's vector, n_p . sum(G n_q v_q), so window
// columns are summed once for a whole run of pixels instead of every pixel
// weighing each neighbour apart.
#pragma once

#include "core/guides.h"
#include "core/window.h"
#include "walkers/separable_mean.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace mcdenoise {

/// Working memory of `dot_weighted_means`.
struct DotScratch {
    std::vector<double> columns;   ///< per column, its vector times its values summed down the window
    std::vector<double> window;    ///< one pixel's window sums of them
};

/// The weighted means of the pixels of [xb, xe) of row y that `chosen`
/// marks (chosen[x - xb] != 0), written `stride` floats apart from `out`
/// (at out + (x - xb) * stride): each pixel's finite neighbours weighted by
/// the spatial kernel times dot(n_p, n_q) of `vectors`, which must be
/// positive for every neighbour of its window (the caller's guarantee).
/// Sums run in double from exact products, in a fixed order, so a pixel's
/// value does not depend on the run it is part of. `vectors` must cover the
/// block. Returns the count of channels with no contribution (set to 0).
int dot_weighted_means(const SeparableSource& src, const NormalPlanes& vectors,
                       int xb, int xe, int y, const uint8_t* chosen, DotScratch& scratch,
                       float* out, std::ptrdiff_t stride);

}  // namespace mcdenoise
