// median_kernel.h: the one median kernel every median filter shares: pruned
// selection networks, unrolled at compile time, that take the median of a
// run of full windows at once (one window per SIMD lane: 16 with AVX-512,
// chosen at run time, else 8), and in-place selection for everything else
// (clipped windows, non-finite values, partial viability).
#pragma once

namespace mcdenoise {

/// The median of `values[0 .. n)` (n >= 1): the middle value for odd n, the
/// mean of the two middle values for even n. Reorders `values`.
float median_in_place(float* values, int n);

/// Medians of the `size` x `size` windows centered at `lanes` consecutive
/// pixels starting at column `x` of `rows` (window row i is `rows[i]`, read
/// at x - r .. x + lanes - 1 + r). Writes `lanes` values.
using WindowMedians = void (*)(const float* const* rows, int x, float* medians);

/// Medians of 8 windows of side `size` given slot by slot: `slots[i * 8 + l]`
/// is value i (row-major in the window) of window l. Writes 8 values.
using SlotMedians = void (*)(const float* slots, float* medians);

/// A network kernel and how many windows it takes at once.
struct MedianKernel {
    WindowMedians run = nullptr;
    int lanes         = 0;
};

/// The 8-lane network for windows of side `size` taking explicit slots
/// (null where no network serves the size). Used for windows only part of
/// which is viable: the others' slots hold -inf and +inf in equal numbers,
/// which leaves the median of the viable values in the middle.
SlotMedians slot_median_kernel(int size);

/// The widest network kernel this processor runs for windows of side
/// `size`, and the 8-lane one (for shorter runs); `run` is null when no
/// network serves that size (sizes above 9 use in-place selection).
MedianKernel wide_median_kernel(int size);
MedianKernel narrow_median_kernel(int size);

/// The number of min/max comparators in the network for `size`, or 0.
int median_network_size(int size);

}  // namespace mcdenoise
