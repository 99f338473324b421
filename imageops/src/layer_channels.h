// layer_channels.h: the forms of clamp_fireflies and denoise that read a
// stacked image: the beauty's channels, then extra light layers (AOVs) as
// further channels, which the outlier scale multiplies like the colour.
#pragma once

#include <mcdenoise/features.h>

#include <OpenImageIO/imagebuf.h>

namespace mcdenoise {

/// `clamp_fireflies`, where channels from `layer_begin` on are scaled by
/// each pixel's factor like the colour channels; channels between the
/// colour and `layer_begin` (alpha) are copied. The factor is decided on
/// the colour alone.
bool clamp_fireflies_layers(OIIO::ImageBuf& dst, const OIIO::ImageBuf& beauty, int layer_begin,
                            const Guides& guides, float factor, int radius, OIIO::ROI roi,
                            int nthreads);

/// `denoise` of a stacked image: every weight and outlier scale is decided
/// on the colour and the guides and applied alike to every channel, the
/// outlier scale to the colour and the channels from `layer_begin` on.
bool denoise_stacked(OIIO::ImageBuf& dst, const OIIO::ImageBuf& beauty, int layer_begin,
                     const Guides& guides, OIIO::ROI roi, int nthreads);

}  // namespace mcdenoise
