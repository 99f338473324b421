// guide_images.cpp: building structured guide images for tests.
#include "guide_images.h"

#include "test_images.h"

#include <cmath>
#include <random>
#include <vector>

namespace testimg {

using OIIO::ImageBuf;
using OIIO::ImageSpec;

namespace {

// Stores `values` in `img` as the nearest whole numbers of type T (OIIO's
// conversion from float would scale them by T's maximum).
template<class T>
void set_whole_numbers(ImageBuf& img, const std::vector<float>& values)
{
    std::vector<T> whole(values.size());
    for (size_t i = 0; i < values.size(); ++i)
        whole[i] = T(std::lround(values[i]));
    img.set_pixels(img.roi(), img.spec().format, whole.data());
}

}  // namespace

ImageBuf from_values(int width, int height, int nchannels, OIIO::TypeDesc format, int x0,
                     int y0, const std::vector<float>& values)
{
    ImageSpec spec(width, height, nchannels, format);
    spec.x = x0;
    spec.y = y0;
    ImageBuf img(spec);
    switch (format.basetype) {
    case OIIO::TypeDesc::UINT8: set_whole_numbers<uint8_t>(img, values); break;
    case OIIO::TypeDesc::UINT16: set_whole_numbers<uint16_t>(img, values); break;
    case OIIO::TypeDesc::UINT32: set_whole_numbers<uint32_t>(img, values); break;
    case OIIO::TypeDesc::INT32: set_whole_numbers<int32_t>(img, values); break;
    default: img.set_pixels(img.roi(), OIIO::TypeDesc::FLOAT, values.data());
    }
    return img;
}

ImageBuf block_ids(int width, int height, uint32_t seed, OIIO::TypeDesc format, int x0,
                   int y0)
{
    std::mt19937 rng(seed);
    std::vector<float> v(size_t(width) * height);
    const int bw = 3 + int(rng() % 9), bh = 3 + int(rng() % 9);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const int block = (x / bw) * 7 + (y / bh) * 3;
            v[size_t(y) * width + x] = float((block * 2654435761u >> 7) % 5);
            if (rng() % 23 == 0)  // a stray pixel of another object
                v[size_t(y) * width + x] = float(rng() % 5);
        }
    return from_values(width, height, 1, format, x0, y0, v);
}

ImageBuf block_reflect_ids(int width, int height, uint32_t seed, int x0, int y0)
{
    std::mt19937 rng(seed);
    std::vector<float> v(size_t(width) * height);
    const int bw = 4 + int(rng() % 8), bh = 4 + int(rng() % 8);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const int block = (x / bw) * 5 + (y / bh);
            const bool specular = (block * 40503u >> 3) % 2 == 0;
            v[size_t(y) * width + x] = specular ? float((x / 3 + y / 4) % 3) : -1.0f;
            if (rng() % 31 == 0)
                v[size_t(y) * width + x] = -7.0f;  // any negative: not specular
        }
    return from_values(width, height, 1, OIIO::TypeDesc::FLOAT, x0, y0, v);
}

ImageBuf wavy_normals(int width, int height, uint32_t seed, int x0, int y0)
{
    std::mt19937 rng(seed);
    std::vector<float> v(size_t(width) * height * 3);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            float* n = &v[(size_t(y) * width + x) * 3];
            const bool flat = (x / 6 + y / 5) % 3 == 0;
            const float scale = 0.5f + float(rng() % 4);
            n[0] = flat ? 0.0f : std::sin(0.4f * x) * scale;
            n[1] = flat ? 2.0f : std::cos(0.3f * y) * scale;
            n[2] = flat ? 0.0f : (std::sin(0.2f * (x + y)) - 0.3f) * scale;
            if (rng() % 19 == 0)
                n[0] = n[1] = n[2] = 0.0f;
        }
    return from_values(width, height, 3, OIIO::TypeDesc::FLOAT, x0, y0, v);
}

testfilters::GuideSet guide_set(int width, int height, uint32_t seed, int x0, int y0)
{
    std::mt19937 rng(seed);
    std::vector<float> depth(size_t(width) * height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            float& d = depth[size_t(y) * width + x];
            d = 1.0f + 0.25f * float(x + y % 7);
            if (rng() % 17 == 0)
                d = 1e10f;
            else if (rng() % 29 == 0)
                d = std::nanf("");
        }
    testfilters::GuideSet g;
    g.object_id  = block_ids(width, height, seed, OIIO::TypeDesc::FLOAT, x0, y0);
    g.reflect_id = block_reflect_ids(width, height, seed + 1, x0, y0);
    g.normal     = wavy_normals(width, height, seed + 2, x0, y0);
    g.depth      = from_values(width, height, 1, OIIO::TypeDesc::FLOAT, x0, y0, depth);
    g.albedo     = random_image(width, height, 3, seed + 3, 0.0f, 1.5f, OIIO::TypeDesc::FLOAT, x0, y0);
    g.variance   = random_image(width, height, 3, seed + 4, 0.0f, 0.1f, OIIO::TypeDesc::FLOAT, x0, y0);
    return g;
}

}  // namespace testimg
