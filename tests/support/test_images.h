// test_images.h: images the unit tests build (random beauty, non-finite
// sprinkles, odd data windows) and the comparisons they make.
#pragma once

#include <OpenImageIO/imagebuf.h>

#include <cstdint>
#include <vector>

namespace testimg {

/// A `width` x `height` image of `nchannels` uniform random values in
/// [lo, hi), stored as `format`, data window origin (x0, y0).
OIIO::ImageBuf random_image(int width, int height, int nchannels, uint32_t seed,
                            float lo = 0.0f, float hi = 1.0f,
                            OIIO::TypeDesc format = OIIO::TypeDesc::FLOAT, int x0 = 0,
                            int y0 = 0);

/// Replace about `fraction` of the values of `img` by NaN, +Inf and -Inf.
void sprinkle_nonfinite(OIIO::ImageBuf& img, double fraction, uint32_t seed);

/// The pixels of `img` over `roi` as floats.
std::vector<float> pixels(const OIIO::ImageBuf& img, OIIO::ROI roi = {});

/// True if both images have the same data window, channels and float bits.
bool bit_identical(const OIIO::ImageBuf& a, const OIIO::ImageBuf& b);

}  // namespace testimg
