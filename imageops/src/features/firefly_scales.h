// firefly_scales.h: the firefly clamp that also says what it did to each
// pixel, for `denoise`'s outlier split (denoise/energy_outliers.h) to do the
// same to further layers.
#pragma once

#include <mcdenoise/features.h>

#include "core/plane.h"

#include <OpenImageIO/imagebuf.h>

namespace mcdenoise {

/// `clamp_fireflies` (fireflies.h), and when `scales` is given the factor
/// it multiplied each pixel's colour by, over the ROI, into `scales`.
bool clamp_fireflies_scales(OIIO::ImageBuf& dst, const OIIO::ImageBuf& beauty,
                            const Guides& guides, float factor, int radius, OIIO::ROI roi,
                            int nthreads, Plane<float>* scales);

}  // namespace mcdenoise
