// bench_images.cpp: a deterministic render-like image for benchmarks.
#include "bench_images.h"

#include <cmath>
#include <random>
#include <vector>

namespace benchimg {

OIIO::ImageBuf noisy_render(int width, int height, int nchannels)
{
    OIIO::ImageBuf img(OIIO::ImageSpec(width, height, nchannels, OIIO::TypeDesc::FLOAT));
    std::mt19937 rng(1234);
    std::exponential_distribution<float> noise(1.0f);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    std::vector<float> px(size_t(width) * height * nchannels);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const float u = float(x) / width, v = float(y) / height;
            const float shade = 0.2f + 0.6f * u * (1.0f - v) + ((x / 240 + y / 180) % 2) * 0.15f;
            const bool firefly = uniform(rng) < 1e-4f;
            for (int c = 0; c < nchannels; ++c)
                px[(size_t(y) * width + x) * nchannels + c]
                    = shade * (0.6f + 0.2f * c) * noise(rng) * (firefly ? 200.0f : 1.0f);
        }
    img.set_pixels(img.roi(), OIIO::TypeDesc::FLOAT, px.data());
    return img;
}

}  // namespace benchimg
