// median_kernel.h: the one median kernel every median filter shares: pruned
// selection networks, unrolled at compile time, that take the median of
// eight full windows at once (one per SIMD lane), and in-place selection for
// everything else (clipped windows, non-finite values, partial viability).
#pragma once

namespace mcdenoise {

/// The median of `values[0 .. n)` (n >= 1): the middle value for odd n, the
/// mean of the two middle values for even n. Reorders `values`.
float median_in_place(float* values, int n);

/// Number of windows a `WindowMedian8` handles at once.
constexpr int median_lanes = 8;

/// Medians of the `size` x `size` windows centered at the 8 consecutive
/// pixels starting at column 0 of `rows`: `rows[i]` points at the center
/// column of window row i (so it reads rows[i][-r .. 7 + r]). Writes 8 values.
using WindowMedian8 = void (*)(const float* const* rows, float* medians);

/// The network kernel for windows of side `size`, or nullptr when no
/// network serves that size (sizes above 9 use in-place selection).
WindowMedian8 window_median8(int size);

/// The number of min/max comparators in the network for `size`, or 0.
int median_network_size(int size);

}  // namespace mcdenoise
