// energy.h: how much of a reference's light an image keeps: the whole
// frame's mean and the brightest pixels' energy, in luminance (features.h's
// weights), and the preset that lost energy, for the denoise quality tests
// and tables.
#pragma once

#include "render_file.h"

#include <OpenImageIO/imagebuf.h>

namespace testimg {

/// The mean luminance of `img` over that of `ref` (same size, RGB first).
double frame_mean_ratio(const OIIO::ImageBuf& img, const OIIO::ImageBuf& ref);

/// Over the brightest `fraction` of `ref`'s pixels (by luminance, at least
/// one pixel): the sum of `img`'s luminance over the sum of `ref`'s.
double brightest_energy_ratio(const OIIO::ImageBuf& img, const OIIO::ImageBuf& ref,
                              double fraction = 0.005);

/// The `denoise` preset before its outlier step kept energy:
/// clamp_fireflies (factor 2, radius 2), then nlmeans with every guide of
/// `r` but the object id and the halves.
OIIO::ImageBuf previous_preset(const Render& r);

}  // namespace testimg
