// test_denoise_layers.cpp: denoise_layers applies the beauty's own
// per-pixel operator to every layer: layers that sum to the beauty sum to
// the denoised beauty, a brute-force reading of each layer pixel as the
// weighted sum of one-hot layers, the beauty bit-identical to denoise's,
// premultiplied alpha kept at or above the colour, a layer's pixels outside
// its data window read as 0, and bad layers refused.
#include <mcdenoise/mcdenoise.h>

#include "passes/layer_steps.h"
#include "support/guide_images.h"
#include "support/test_images.h"

#include <OpenImageIO/imagebufalgo.h>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace {

using OIIO::ImageBuf;
using OIIO::ROI;
namespace IBA = OIIO::ImageBufAlgo;

/// Colour channels of `img` (the first three) as an RGB image.
ImageBuf rgb(const ImageBuf& img) { return IBA::channels(img, 3, { 0, 1, 2 }); }

/// A noisy RGBA beauty with one firefly, premultiplied: colour <= alpha.
ImageBuf noisy_rgba(int w, int h, uint32_t seed)
{
    ImageBuf alpha  = testimg::random_image(w, h, 1, seed + 1, 0.2f, 1.0f);
    ImageBuf colour = testimg::random_image(w, h, 3, seed, 0.0f, 1.0f);
    colour          = IBA::mul(colour, IBA::channels(alpha, 3, { 0, 0, 0 }));
    ImageBuf out    = IBA::channel_append(colour, alpha);
    // a firefly: bright colour, premultiplied by a full alpha
    const float firefly[4] = { 40.0f, 40.0f, 40.0f, 1.0f };
    out.setpixel(w / 2, h / 2, firefly, 4);
    return out;
}

/// Three layers of random shares that sum to the colour of `beauty`.
std::vector<ImageBuf> shares_of(const ImageBuf& beauty, uint32_t seed)
{
    const ImageBuf colour = rgb(beauty);
    const ImageBuf a      = IBA::mul(colour, testimg::random_image(colour.spec().width,
                                                                   colour.spec().height, 3, seed));
    const ImageBuf rest   = IBA::sub(colour, a);
    const ImageBuf b      = IBA::mul(rest, 0.25f);
    return { a, b, IBA::sub(rest, b) };
}

std::vector<const ImageBuf*> pointers(const std::vector<ImageBuf>& images)
{
    std::vector<const ImageBuf*> out;
    for (const ImageBuf& img : images)
        out.push_back(&img);
    return out;
}

/// Every guide `denoise` reads, over w x h.
struct Guides {
    testfilters::GuideSet set;
    mcdenoise::Guides view;
    Guides(int w, int h, uint32_t seed)
        : set(testimg::guide_set(w, h, seed))
    {
        view.normal   = &set.normal;
        view.depth    = &set.depth;
        view.albedo   = &set.albedo;
        view.variance = &set.variance;
    }
};

TEST(DenoiseLayers, LayersThatSumToTheBeautySumToTheDenoisedBeauty)
{
    const ImageBuf beauty = noisy_rgba(40, 32, 11);
    const Guides guides(40, 32, 3);
    for (const mcdenoise::Guides& g : { mcdenoise::Guides {}, guides.view }) {
        const std::vector<ImageBuf> layers = shares_of(beauty, 5);
        ImageBuf out;
        std::vector<ImageBuf> out_layers;
        ASSERT_TRUE(mcdenoise::denoise_layers(out, out_layers, beauty, pointers(layers), g))
            << out.geterror();
        ASSERT_EQ(out_layers.size(), 3u);
        const ImageBuf sum = IBA::add(IBA::add(out_layers[0], out_layers[1]), out_layers[2]);
        EXPECT_LE(mcdenoise::rel_mse(sum, rgb(out)), 1e-6);
        // and the noise is gone from each layer as from the beauty
        EXPECT_GT(mcdenoise::rel_mse(layers[0], out_layers[0]), 1e-3);
    }
}

/// A premultiplied RGBA beauty whose luminances lie within a factor 1.6 of
/// each other: no pixel is above the firefly bound, so nothing is split.
ImageBuf calm_rgba(int w, int h, uint32_t seed)
{
    const ImageBuf alpha  = testimg::random_image(w, h, 1, seed + 1, 0.9f, 1.0f);
    const ImageBuf colour = testimg::random_image(w, h, 3, seed, 0.35f, 0.5f);
    return IBA::channel_append(colour, alpha);
}

/// The per-pixel operator `denoise_layers` applies to `beauty`'s layers,
/// measured with one one-hot layer per pixel: M(p, q) is pixel p of the
/// result of the layer that is 1 at q. Checks that a further layer L comes
/// out as sum_q M L(q) and the beauty's colour as sum_q M C(q); returns M
/// (M[q] an image over the beauty).
std::vector<ImageBuf> check_shared_operator(const ImageBuf& beauty, ImageBuf& out)
{
    const int w = beauty.spec().width, h = beauty.spec().height;
    const ImageBuf layer = testimg::random_image(w, h, 2, 8, -1.0f, 2.0f);
    std::vector<ImageBuf> hots;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            ImageBuf hot    = testimg::random_image(w, h, 1, 1, 0.0f, 0.0f);
            const float one = 1.0f;
            hot.setpixel(x, y, &one, 1);
            hots.push_back(hot);
        }
    std::vector<const ImageBuf*> layers = pointers(hots);
    layers.push_back(&layer);
    std::vector<ImageBuf> outs;
    EXPECT_TRUE(mcdenoise::denoise_layers_steps(mcdenoise::LayerSteps::beauty_operator, out, outs,
                                                    beauty, layers, {}, {}, {}, 0)) << out.geterror();
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double expect_layer[2] = {}, expect_colour[3] = {};
            for (int q = 0; q < w * h; ++q) {
                const int qx = q % w, qy = q / w;
                const double m = outs[size_t(q)].getchannel(x, y, 0, 0);
                for (int c = 0; c < 2; ++c)
                    expect_layer[c] += m * layer.getchannel(qx, qy, 0, c);
                for (int c = 0; c < 3; ++c)
                    expect_colour[c] += m * beauty.getchannel(qx, qy, 0, c);
            }
            for (int c = 0; c < 2; ++c)
                EXPECT_NEAR(outs.back().getchannel(x, y, 0, c), expect_layer[c], 1e-5)
                    << x << "," << y;
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(out.getchannel(x, y, 0, c), expect_colour[c],
                            1e-5 * (1 + std::abs(expect_colour[c])))
                    << x << "," << y;
        }
    outs.pop_back();
    return outs;
}

TEST(DenoiseLayers, EveryLayerGetsTheBeautysOwnPerPixelOperator)
{
    // With a firefly: the split (the bound averaged, the excess given back)
    // and the weights act alike on the colour and on every layer.
    const int w = 12, h = 10;
    ImageBuf out;
    const std::vector<ImageBuf> m = check_shared_operator(noisy_rgba(w, h, 21), out);
    // the firefly was split: little of it stays where it was
    EXPECT_LT(m[size_t(h / 2 * w + w / 2)].getchannel(w / 2, h / 2, 0, 0), 0.25f);
}

TEST(DenoiseLayers, AlphaGetsTheWeightsAlone)
{
    // With nothing split the operator is the NL-means weights W, and alpha,
    // never split, comes out as sum_q W A(q) too.
    const int w = 12, h = 10;
    const ImageBuf beauty = calm_rgba(w, h, 23);
    ImageBuf out;
    const std::vector<ImageBuf> m = check_shared_operator(beauty, out);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double expect_alpha = 0;
            for (int q = 0; q < w * h; ++q)
                expect_alpha += m[size_t(q)].getchannel(x, y, 0, 0)
                                * beauty.getchannel(q % w, q / w, 0, 3);
            EXPECT_NEAR(out.getchannel(x, y, 0, 3), expect_alpha, 1e-5) << x << "," << y;
        }
}

TEST(DenoiseLayers, ANoiseFreeEdgeStaysWhereTheBeautysWeightsBlurIt)
{
    // A direct pass with a hard shadow edge and no noise, an indirect pass
    // with strong noise: the weights the noise sets blur the edge, and the
    // back-off returns the direct pass to its own values.
    const int w = 40, h = 32;
    ImageBuf direct = testimg::random_image(w, h, 3, 1, 0.0f, 0.0f);
    IBA::fill(direct, { 1.0f, 1.0f, 1.0f }, ROI(w / 2, w, 0, h));
    const ImageBuf indirect = testimg::random_image(w, h, 3, 41, 0.0f, 2.0f);
    const ImageBuf beauty   = IBA::add(direct, indirect);
    ImageBuf shared_out, own_out;
    std::vector<ImageBuf> shared, own;
    ASSERT_TRUE(mcdenoise::denoise_layers_steps(mcdenoise::LayerSteps::beauty_operator, shared_out,
                                                shared, beauty, { &direct, &indirect }, {}, {}, {},
                                                0));
    ASSERT_TRUE(mcdenoise::denoise_layers(own_out, own, beauty, { &direct, &indirect }));
    const double blurred = mcdenoise::rel_mse(shared[0], direct);
    EXPECT_GT(blurred, 1e-3);
    EXPECT_LT(mcdenoise::rel_mse(own[0], direct), 0.1 * blurred);
    // the indirect pass (uniform noise around 1) is still denoised, and
    // the two add up
    ImageBuf one = testimg::random_image(w, h, 3, 1, 1.0f, 1.0f);
    EXPECT_LT(mcdenoise::rel_mse(own[1], one), 0.5 * mcdenoise::rel_mse(indirect, one));
    EXPECT_LE(mcdenoise::rel_mse(IBA::add(own[0], own[1]), rgb(own_out)), 1e-6);
}

TEST(DenoiseLayers, TheBeautyIsBitIdenticalToDenoisesWithAnyLayers)
{
    const ImageBuf beauty = noisy_rgba(37, 29, 31);
    const Guides guides(37, 29, 4);
    ImageBuf nan_layer = testimg::random_image(37, 29, 3, 9);
    testimg::sprinkle_nonfinite(nan_layer, 0.05, 2);
    const ImageBuf one = testimg::random_image(37, 29, 1, 10);
    for (const mcdenoise::Guides& g : { mcdenoise::Guides {}, guides.view }) {
        const ImageBuf alone = mcdenoise::denoise(beauty, g);
        ImageBuf out;
        std::vector<ImageBuf> outs;
        ASSERT_TRUE(mcdenoise::denoise_layers(out, outs, beauty, { &nan_layer, &one }, g));
        EXPECT_TRUE(testimg::bit_identical(out, alone));
        const ROI part(3, 30, 2, 20);
        ImageBuf part_out;
        std::vector<ImageBuf> part_outs;
        ASSERT_TRUE(mcdenoise::denoise_layers(part_out, part_outs, beauty, { &one }, g, {}, part));
        EXPECT_TRUE(testimg::bit_identical(part_out, mcdenoise::denoise(beauty, g, part)));
        EXPECT_EQ(part_outs[0].roi(), ROI(3, 30, 2, 20, 0, 1, 0, 1));
    }
}

TEST(DenoiseLayers, ALayerReadsAsZeroOutsideItsDataWindow)
{
    const ImageBuf beauty = noisy_rgba(30, 24, 61);
    const ImageBuf full   = testimg::random_image(30, 24, 3, 12);
    const ROI inner(6, 22, 5, 19, 0, 1, 0, 3);
    const ImageBuf cropped = IBA::crop(full, inner);  // data window inner only
    ImageBuf padded        = IBA::zero(ROI(0, 30, 0, 24, 0, 1, 0, 3));
    ASSERT_TRUE(IBA::copy(padded, full, OIIO::TypeUnknown, inner));
    const ROI part(8, 20, 7, 17);
    ImageBuf a, b;
    std::vector<ImageBuf> from_cropped, from_padded;
    ASSERT_TRUE(mcdenoise::denoise_layers(a, from_cropped, beauty, { &cropped }, {}, {}, part)) << a.geterror();
    ASSERT_TRUE(mcdenoise::denoise_layers(b, from_padded, beauty, { &padded }, {}, {}, part));
    EXPECT_TRUE(testimg::bit_identical(from_cropped[0], from_padded[0]));
}

TEST(DenoiseLayers, PremultipliedColourStaysAtOrBelowAlpha)
{
    const ImageBuf beauty = noisy_rgba(48, 40, 41);
    const std::vector<ImageBuf> layers = shares_of(beauty, 6);
    const std::vector<ImageBuf> out = mcdenoise::denoise_layers(beauty, pointers(layers));
    ASSERT_EQ(out.size(), 4u);
    ASSERT_FALSE(out[0].has_error()) << out[0].geterror();
    int translucent = 0;
    for (int y = 0; y < 40; ++y)
        for (int x = 0; x < 48; ++x) {
            const float a = out[0].getchannel(x, y, 0, 3);
            translucent += a < 0.9f;
            for (int c = 0; c < 3; ++c)
                EXPECT_LE(out[0].getchannel(x, y, 0, c), a) << x << "," << y << " c" << c;
        }
    EXPECT_GT(translucent, 100);
}

TEST(DenoiseLayers, BadLayersAreRefusedByName)
{
    const ImageBuf beauty = noisy_rgba(16, 16, 51);
    const ImageBuf small  = testimg::random_image(8, 16, 3, 1);
    const ImageBuf empty;
    for (const ImageBuf* bad : { &small, &empty, static_cast<const ImageBuf*>(nullptr) }) {
        const ImageBuf good = testimg::random_image(16, 16, 3, 2);
        ImageBuf out;
        std::vector<ImageBuf> outs;
        EXPECT_FALSE(mcdenoise::denoise_layers(out, outs, beauty, { &good, bad }));
        EXPECT_NE(out.geterror().find("layer 1"), std::string::npos) << out.geterror();
        EXPECT_FALSE(out.initialized());
    }
}

}  // namespace
