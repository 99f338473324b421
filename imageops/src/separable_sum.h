// separable_sum.h: weighted window sums with a separable spatial kernel (box
// or binomial), the fast path of every weighted-mean filter. Box sums slide
// (cost independent of the size); other kernels are applied row then column.
#pragma once

#include "pixel_block.h"

#include <vector>

namespace mcdenoise {

/// The 1D taps of a separable window of side 2 * radius + 1.
struct Kernel1D {
    int radius = 0;
    bool box   = false;          ///< all taps 1: summed with sliding sums
    std::vector<double> weights; ///< 2 * radius + 1 taps
};

/// All-ones taps of a box window of side `size`.
Kernel1D box_kernel(int size);

/// Row `size - 1` of Pascal's triangle, scaled by 2^-(size-1) so that large
/// sizes stay in range (the scale cancels in every weighted mean).
Kernel1D binomial_kernel(int size);

/// The source rectangle `separable_sums` reads to produce `roi`: `roi` grown
/// by the radius (box sums also reach back to their restart points), clipped
/// to the data window `bounds`.
OIIO::ROI separable_source_region(const OIIO::ROI& roi, const Kernel1D& kernel,
                                  const OIIO::ROI& bounds);

/// Where sliding sums restart: the data window's origin.
struct SumOrigin {
    int x = 0;
    int y = 0;
};

/// For each pixel of `strip` and each channel of `src`, the kernel-weighted
/// sum over the window clipped to `src.region` (which must hold
/// `separable_source_region(strip)`). Writes strip.width() * src.nchannels
/// doubles per row, rows consecutive, to `sums`. The result for a pixel does
/// not depend on `strip`.
void separable_sums(const PixelBlock& src, const Kernel1D& kernel,
                    SumOrigin origin, const OIIO::ROI& strip, double* sums);

/// The total weight of the window centered at (x, y) clipped to `region`,
/// accumulated in the same order as `separable_sums` so that it equals the
/// sums of an all-ones channel bit for bit.
double window_weight(const Kernel1D& kernel, int x, int y, const OIIO::ROI& region);

}  // namespace mcdenoise
