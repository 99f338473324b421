// separable_mean.h: the weighted mean with a separable spatial kernel (box or
// binomial) over the finite values of each window: the simple mean and
// gaussian, and the fast path of every guided weighted-mean filter wherever a
// whole window is viable. Wide box sums slide in double precision (cost
// independent of the size); narrow boxes and binomial windows run column
// then row in float SIMD. Sliding sums restart at fixed points, so a pixel's
// value never depends on the strip or ROI it was computed in.
#pragma once

#include "core/operation.h"
#include "core/pixel_block.h"
#include "core/window.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace mcdenoise {

/// The 1D taps of a separable window of side 2 * radius + 1.
struct Kernel1D {
    int radius = 0;
    bool sliding = false;       ///< all taps 1 and wide: summed with sliding sums
    std::vector<float> weights; ///< 2 * radius + 1 taps
};

/// All-ones taps of a box window of side `size`. Windows wider than
/// `max_direct_box_size` are summed with sliding sums, narrower ones tap by
/// tap like the binomial (faster below the crossover on 1080p frames).
Kernel1D box_kernel(int size);

/// The widest box window summed tap by tap (measured in docs/benchmarks.md).
constexpr int max_direct_box_size = 11;

/// Row `size - 1` of Pascal's triangle, scaled to sum to 1 (the scale
/// cancels in every weighted mean, and keeps large sizes in range).
Kernel1D binomial_kernel(int size);

/// The beauty as the separable mean reads it: the pixels the kernel reaches
/// from the ROI, as `with_finite_mask` gives them when any value is
/// non-finite or beyond `max_summed_magnitude`.
struct SeparableSource {
    Kernel1D kernel;
    std::shared_ptr<const PixelBlock> pixels;  ///< may be shared by several kernels
    int nchannels = 0;  ///< beauty channels (the block has twice that when masked)
    bool masked   = false;
    int origin_x = 0, origin_y = 0;  ///< the data window's origin: restart anchor

    const PixelBlock& block() const { return *pixels; }
};

/// Read `beauty` over what `kernel` reaches from `roi`.
/// Returns false with `dst`'s error set if the pixels cannot be read.
bool load_separable_source(const char* op, OIIO::ImageBuf& dst,
                           const OIIO::ImageBuf& beauty, const OIIO::ROI& roi,
                           Kernel1D kernel, int nthreads, SeparableSource& source);

/// Use `block` (already read, covering what `kernel` reaches from the ROI
/// within `bounds`, the data window) as a separable source.
void make_separable_source(PixelBlock block, const OIIO::ROI& bounds, Kernel1D kernel,
                           int nthreads, SeparableSource& source);

/// The same pixels as `source`, summed with another kernel (whose reach
/// from the ROI the block must cover).
SeparableSource with_kernel(const SeparableSource& source, Kernel1D kernel);

/// The block region a separable source needs to produce `roi`.
OIIO::ROI separable_source_region(const OIIO::ROI& roi, const Kernel1D& kernel,
                                  const OIIO::ROI& bounds);

/// The kernel-weighted means of one strip, produced row by row, top to
/// bottom; rows may be skipped. A pixel's value does not depend on the strip.
class SeparableMeanRows {
public:
    SeparableMeanRows(const SeparableSource& source, const OIIO::ROI& strip);
    ~SeparableMeanRows();

    /// Write row `y`'s means (strip.width() pixels, `stride` floats apart,
    /// the source's channels each) to `out`; returns the count of empty
    /// windows. When `empty_per_pixel` is given, it receives each pixel's
    /// count of channels whose window held no finite value.
    int64_t row(int y, float* out, std::ptrdiff_t stride, uint8_t* empty_per_pixel);

    /// `row` for the pixels `xs` (inside the strip) only: `out` and
    /// `empty_per_pixel` still start at the strip's first pixel, and the
    /// other pixels are left alone.
    int64_t row(int y, Span xs, float* out, std::ptrdiff_t stride, uint8_t* empty_per_pixel);

private:
    OIIO::ROI m_strip;
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

/// The kernel-weighted mean of the finite values in each pixel's window, for
/// every pixel and channel of `strip`, into `result`. Windows with no finite
/// value give 0 and are counted.
void separable_mean_strip(const SeparableSource& source, const OIIO::ROI& strip,
                          ResultPixels& result);

}  // namespace mcdenoise
