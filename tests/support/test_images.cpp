// test_images.cpp: building and comparing test images.
#include "test_images.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

namespace testimg {

using OIIO::ImageBuf;
using OIIO::ImageSpec;
using OIIO::ROI;

ImageBuf random_image(int width, int height, int nchannels, uint32_t seed, float lo,
                      float hi, OIIO::TypeDesc format, int x0, int y0)
{
    ImageSpec spec(width, height, nchannels, format);
    spec.x = x0;
    spec.y = y0;
    spec.full_x = 0;
    spec.full_y = 0;
    ImageBuf img(spec);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> dist(lo, hi);
    std::vector<float> values(size_t(width) * height * nchannels);
    for (float& v : values)
        v = dist(rng);
    img.set_pixels(img.roi(), OIIO::TypeDesc::FLOAT, values.data());
    return img;
}

void sprinkle_nonfinite(ImageBuf& img, double fraction, uint32_t seed)
{
    std::vector<float> values = pixels(img);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> pick(0.0, 1.0);
    const float specials[3] = { std::numeric_limits<float>::quiet_NaN(),
                                std::numeric_limits<float>::infinity(),
                                -std::numeric_limits<float>::infinity() };
    for (float& v : values)
        if (pick(rng) < fraction)
            v = specials[rng() % 3];
    img.set_pixels(img.roi(), OIIO::TypeDesc::FLOAT, values.data());
}

std::vector<float> pixels(const ImageBuf& img, ROI roi)
{
    if (!roi.defined())
        roi = img.roi();
    std::vector<float> out(size_t(roi.width()) * roi.height() * roi.nchannels());
    img.get_pixels(roi, OIIO::TypeDesc::FLOAT, out.data());
    return out;
}

bool bit_identical(const ImageBuf& a, const ImageBuf& b)
{
    if (a.roi() != b.roi())
        return false;
    const std::vector<float> pa = pixels(a), pb = pixels(b);
    return std::memcmp(pa.data(), pb.data(), pa.size() * sizeof(float)) == 0;
}

}  // namespace testimg
