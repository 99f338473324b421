// test_quality.cpp: the report's filters against testrender ground truth
// (the cached reference set, CTest fixture `refset`): what the report claims,
// checked in relMSE with thresholds set from the measured numbers recorded in
// docs/quality_refset.md, including where the claims do not hold on our scenes.
#include <mcdenoise/mcdenoise.h>

#include "support/render_file.h"

#include <OpenImageIO/imagebufalgo.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

using OIIO::ImageBuf;
using testimg::Render;

std::string refset_file(const std::string& name)
{
    const char* dir = std::getenv("MCD_REFSET_DIR");
    return std::string(dir ? dir : MCD_REFSET_DIR_DEFAULT) + "/" + name + ".exr";
}

// A scene at `spp` and its reference.
struct SceneAt {
    Render noisy, ref;
    SceneAt(const std::string& scene, int spp)
        : noisy(testimg::read_render(refset_file(scene + "_" + std::to_string(spp))))
        , ref(testimg::read_render(refset_file(scene + "_ref")))
    {
        EXPECT_EQ(noisy.error, "");
        EXPECT_EQ(ref.error, "");
    }
    double rel_mse(const ImageBuf& img) const { return mcdenoise::rel_mse(img, ref.beauty); }
    // relMSE over pixels whose 3x3 window is one object (away from edges).
    double rel_mse_inside(const ImageBuf& img) const
    {
        return testimg::masked_rel_mse(img, ref.beauty,
                                       testimg::single_object_pixels(ref.object_id, 3));
    }
    // relMSE over specular pixels (reflect id >= 0).
    double rel_mse_specular(const ImageBuf& img) const
    {
        return testimg::masked_rel_mse(img, ref.beauty,
                                       OIIO::ImageBufAlgo::add(ref.reflect_id, 1.0f));
    }
};

class AtSpp : public ::testing::TestWithParam<int> {};

// Measured at 16 / 32 spp: cornell object_median 7 is 0.84 / 0.82 of median 7.
TEST_P(AtSpp, ObjectMedianKeepsEdgesBetterThanMedianOnCornell)
{
    const SceneAt s("cornell", GetParam());
    const Render& r = s.noisy;
    EXPECT_LT(s.rel_mse(mcdenoise::object_median(r.beauty, r.object_id, 7)),
              0.95 * s.rel_mse(mcdenoise::median(r.beauty, 7)));
}

// The report never tried a textured scene: a 7x7 median erases the texture.
// Measured: both medians multiply relMSE about 20x over the raw render, and
// the object median is within 2% of the plain one (edges matter little once
// the texture is gone). The beyond-the-report issue answers this with albedo
// demodulation.
TEST_P(AtSpp, MediansEraseTextureOnTextured)
{
    const SceneAt s("textured", GetParam());
    const Render& r     = s.noisy;
    const double raw    = s.rel_mse(r.beauty);
    const double median = s.rel_mse(mcdenoise::median(r.beauty, 7));
    const double object = s.rel_mse(mcdenoise::object_median(r.beauty, r.object_id, 7));
    EXPECT_GT(median, 10 * raw);
    EXPECT_GT(object, 10 * raw);
    EXPECT_NEAR(object / median, 1.0, 0.1);
}

// Measured on mirrors' specular pixels: brdf_mean 3 is 0.15, brdf_gaussian 3
// 0.19 of their object counterparts; size 7 0.07 and 0.11.
TEST_P(AtSpp, BrdfFiltersKeepReflectionsOnMirrors)
{
    const SceneAt s("mirrors", GetParam());
    const Render& r = s.noisy;
    for (int size : { 3, 7 }) {
        EXPECT_LT(s.rel_mse_specular(mcdenoise::brdf_mean(r.beauty, r.object_id, r.reflect_id, size)),
                  0.5 * s.rel_mse_specular(mcdenoise::object_mean(r.beauty, r.object_id, size)));
        EXPECT_LT(s.rel_mse_specular(
                      mcdenoise::brdf_gaussian(r.beauty, r.object_id, r.reflect_id, size)),
                  0.5 * s.rel_mse_specular(mcdenoise::object_gaussian(r.beauty, r.object_id, size)));
    }
}

// The report's best chain. Measured on cornell at 16 / 32 spp: away from
// object edges 0.081 / 0.127 of the raw relMSE; over the whole image it is
// 6.5x / 13x the raw relMSE, because the simple gaussian 3 smears the
// visible area light into its dark neighbours (a few pixels dominate).
TEST_P(AtSpp, BestChainCleansCornellAwayFromEdges)
{
    const SceneAt s("cornell", GetParam());
    const ImageBuf chain = testimg::best_chain(s.noisy);
    EXPECT_LT(s.rel_mse_inside(chain), 0.3 * s.rel_mse_inside(s.noisy.beauty));
}

// Measured on interior at 16 / 32 spp: 0.15 / 0.16 of the raw relMSE.
TEST_P(AtSpp, BestChainCleansInterior)
{
    const SceneAt s("interior", GetParam());
    EXPECT_LT(s.rel_mse(testimg::best_chain(s.noisy)), 0.4 * s.rel_mse(s.noisy.beauty));
}

INSTANTIATE_TEST_SUITE_P(RefSet, AtSpp, ::testing::Values(16, 32),
                         [](const auto& info) { return std::to_string(info.param) + "spp"; });

// At 16 spp the chain halves relMSE on dof (measured 0.53); at 32 spp it no
// longer helps (1.05): defocused edges are soft in the beauty but sharp in
// the id buffer, and the noise it removes has halved.
TEST(BestChain, HalvesRelMseOnDofAt16Spp)
{
    const SceneAt s("dof", 16);
    EXPECT_LT(s.rel_mse(testimg::best_chain(s.noisy)), 0.7 * s.rel_mse(s.noisy.beauty));
}

// On mirrors the object median mixes different reflections on one mirror:
// away from edges the chain is 0.81 of raw at 16 spp but 1.6x at 32 spp.
TEST(BestChain, HelpsMirrorsAwayFromEdgesOnlyAt16Spp)
{
    const SceneAt s16("mirrors", 16), s32("mirrors", 32);
    EXPECT_LT(s16.rel_mse_inside(testimg::best_chain(s16.noisy)),
              0.95 * s16.rel_mse_inside(s16.noisy.beauty));
    EXPECT_GT(s32.rel_mse_inside(testimg::best_chain(s32.noisy)),
              s32.rel_mse_inside(s32.noisy.beauty));
}

// The denoise preset at 16 spp on every scene, against the raw render at 16x
// the samples and against the report's best chain. The printed figures are
// the ones docs/quality.md records.
class DenoiseOn : public ::testing::TestWithParam<const char*> {
protected:
    void SetUp() override
    {
        const SceneAt s(GetParam(), 16);
        const SceneAt many(GetParam(), 256);
        denoised   = s.rel_mse(mcdenoise::denoise(s.noisy.beauty, s.noisy.guides()));
        alone      = s.rel_mse(mcdenoise::denoise(s.noisy.beauty));
        raw_256    = many.rel_mse(many.noisy.beauty);
        chain      = s.rel_mse(testimg::best_chain(s.noisy));
        gaussian_7 = s.rel_mse(mcdenoise::gaussian(s.noisy.beauty, 7));
        raw_16     = s.rel_mse(s.noisy.beauty);
        std::printf("%s: denoise %.5f, beauty only %.5f, raw 16 spp %.5f, raw 256 spp %.5f, "
                    "chain %.5f, gaussian 7 %.5f\n",
                    GetParam(), denoised, alone, raw_16, raw_256, chain, gaussian_7);
    }
    double denoised = 0, alone = 0, raw_16 = 0, raw_256 = 0, chain = 0, gaussian_7 = 0;
};

TEST_P(DenoiseOn, HalvesTheBestChainsError)
{
    EXPECT_LT(denoised, 0.5 * chain);
}

TEST_P(DenoiseOn, BeautyAloneBeatsGaussian7)
{
    EXPECT_LT(alone, gaussian_7);
}

// 16x fewer samples for the same error. Measured denoise / raw 256 spp:
// cornell 0.58, mirrors 0.90, interior 0.46. Not reached on textured (7.3x)
// and dof (2.2x), where denoise is 0.55 and 0.16 of the raw 16 spp error:
// there sub-pixel texture and defocus leave a bias the features cannot
// explain (docs/quality.md).
TEST_P(DenoiseOn, BeatsRaw256SppOnSmoothlyLitScenes)
{
    const std::string scene = GetParam();
    if (scene == "textured" || scene == "dof")
        EXPECT_LT(denoised, 0.7 * raw_16);
    else
        EXPECT_LT(denoised, raw_256);
}

INSTANTIATE_TEST_SUITE_P(RefSet, DenoiseOn,
                         ::testing::Values("cornell", "mirrors", "textured", "dof", "interior"));

}  // namespace
