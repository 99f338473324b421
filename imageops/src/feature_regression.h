// feature_regression.h: `denoise`'s average as a first-order regression of
// the colour on the feature guides (NFOR's features as regressors), with
// the NL-means weights of `denoise`.
#pragma once

#include "denoise_frame.h"

#include <OpenImageIO/imagebuf.h>

namespace mcdenoise {

/// Filter `frame.clamped` over `roi` with `denoise`'s NL-means weights,
/// fitting per pixel, per colour channel, the colour as an affine function
/// of the feature guides present (ridge-regularised weighted least squares
/// over the search window) and evaluating it at the pixel's own features.
/// Without feature guides this is `nlmeans`. On failure sets `dst`'s error.
bool regression_average(OIIO::ImageBuf& dst, const DenoiseFrame& frame, const OIIO::ROI& roi,
                        int nthreads);

}  // namespace mcdenoise
