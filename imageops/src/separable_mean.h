// separable_mean.h: the weighted mean with a separable spatial kernel over a
// whole ROI: the simple mean and gaussian, and the fast path of every guided
// weighted-mean filter where the whole window is viable.
#pragma once

#include "operation.h"
#include "separable_sum.h"

namespace mcdenoise {

/// The kernel-weighted mean of the finite values in each pixel's window,
/// over every pixel and channel of `result.roi`, computed from `beauty` on
/// `nthreads` threads. Windows with no finite value give 0 and are counted.
/// Returns false with `dst`'s error set if the pixels cannot be read.
bool separable_mean(const char* op, OIIO::ImageBuf& dst, const OIIO::ImageBuf& beauty,
                    const Kernel1D& kernel, int nthreads, ResultPixels& result);

}  // namespace mcdenoise
