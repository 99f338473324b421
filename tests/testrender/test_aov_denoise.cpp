// test_aov_denoise.cpp: denoise_layers on testrender's light passes: the
// per-lobe light (colour times direct and indirect irradiance), emission
// and environment sum to the beauty, and their denoised forms sum to the
// denoised beauty; on the transparent scene the premultiplied colour stays
// at or below the denoised alpha.
#include "passes.h"
#include "render.h"
#include "scene.h"

#include <mcdenoise/mcdenoise.h>

#include <OpenImageIO/imagebufalgo.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

using OIIO::ImageBuf;
using namespace testrender;

/// `n` channels per pixel of `values` as a w x h float image.
ImageBuf image(const RenderBuffers& b, const std::vector<float>& values, int n)
{
    ImageBuf img(OIIO::ImageSpec(b.width, b.height, n, OIIO::TypeDesc::FLOAT));
    img.set_pixels(img.roi(), OIIO::TypeDesc::FLOAT, values.data());
    return img;
}

/// The light layers a compositor adds up: per lobe colour x direct and
/// colour x indirect, then emission and environment.
std::vector<ImageBuf> light_layers(const RenderBuffers& b)
{
    const ImageBuf all = image(b, b.passes, pass_channels);
    const auto pass    = [&](int offset) {
        return OIIO::ImageBufAlgo::channels(all, 3, { offset, offset + 1, offset + 2 });
    };
    std::vector<ImageBuf> layers;
    for (int lobe = 0; lobe < lobe_count; ++lobe)
        for (int light = 0; light < 2; ++light)
            layers.push_back(OIIO::ImageBufAlgo::mul(pass(9 * lobe + 6), pass(9 * lobe + 3 * light)));
    layers.push_back(pass(27));
    layers.push_back(pass(30));
    return layers;
}

class SceneLayers : public ::testing::TestWithParam<std::string> {};

TEST_P(SceneLayers, DenoisedLightPassesSumToTheDenoisedBeauty)
{
    Scene scene;
    ASSERT_TRUE(make_scene(GetParam(), scene));
    RenderSettings settings;
    settings.width  = 40;
    settings.height = 30;
    settings.spp    = 4;
    settings.passes = true;
    const RenderBuffers b = render(scene, settings);
    ImageBuf beauty = image(b, b.beauty, 3);
    if (!b.alpha.empty())
        beauty = OIIO::ImageBufAlgo::channel_append(beauty, image(b, b.alpha, 1));
    const ImageBuf normal = image(b, b.normal, 3), albedo = image(b, b.albedo, 3),
                   depth = image(b, b.depth, 1), variance = image(b, b.variance, 3);
    mcdenoise::Guides guides;
    guides.normal   = &normal;
    guides.albedo   = &albedo;
    guides.depth    = &depth;
    guides.variance = &variance;
    const std::vector<ImageBuf> layers = light_layers(b);
    std::vector<const ImageBuf*> pointers;
    for (const ImageBuf& l : layers)
        pointers.push_back(&l);
    ImageBuf out;
    std::vector<ImageBuf> outs;
    ASSERT_TRUE(mcdenoise::denoise_layers(out, outs, beauty, pointers, guides)) << out.geterror();
    ImageBuf sum = outs[0];
    for (size_t i = 1; i < outs.size(); ++i)
        sum = OIIO::ImageBufAlgo::add(sum, outs[i]);
    const ImageBuf colour = OIIO::ImageBufAlgo::channels(out, 3, { 0, 1, 2 });
    EXPECT_LE(mcdenoise::rel_mse(sum, colour), 1e-6);
    EXPECT_GT(mcdenoise::rel_mse(image(b, b.beauty, 3), colour), 1e-3);  // it did denoise
    if (b.alpha.empty())
        return;
    int translucent = 0;
    for (int y = 0; y < b.height; ++y)
        for (int x = 0; x < b.width; ++x) {
            const float a = out.getchannel(x, y, 0, 3);
            translucent += a < 0.99f;
            for (int c = 0; c < 3; ++c)
                EXPECT_LE(out.getchannel(x, y, 0, c), a) << x << "," << y;
        }
    EXPECT_GT(translucent, 0);
}

INSTANTIATE_TEST_SUITE_P(Scenes, SceneLayers,
                         ::testing::Values("cornell", "textured", "transparent"));

}  // namespace
