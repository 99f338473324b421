// test_quality.cpp: the report's filters against testrender ground truth
// (the cached reference set, CTest fixture `refset`): what the report claims,
// checked in relMSE with thresholds set from the measured numbers recorded in
// docs/quality_refset.md, including where the claims do not hold on our scenes.
#include <mcdenoise/mcdenoise.h>

#include "support/energy.h"
#include "support/render_file.h"

#include <OpenImageIO/imagebufalgo.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <tuple>

namespace {

using OIIO::ImageBuf;
using testimg::previous_preset;
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
// cornell 0.57, mirrors 0.87, interior 0.38. Not reached on textured (7.3x)
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

const char* const all_scenes[] = { "cornell", "mirrors", "textured", "dof",
                                   "interior", "metal",  "bokeh",    "dim" };

// denoise with every guide on a scene at an spp. The figures are
// docs/denoise.md's (bench/denoise_table).
class DenoiseEnergy : public ::testing::TestWithParam<std::tuple<const char*, int>> {
protected:
    void SetUp() override
    {
        const SceneAt s(std::get<0>(GetParam()), std::get<1>(GetParam()));
        const ImageBuf out = mcdenoise::denoise(s.noisy.beauty, s.noisy.guides());
        mean_ratio         = testimg::frame_mean_ratio(out, s.ref.beauty);
        input_mean_ratio   = testimg::frame_mean_ratio(s.noisy.beauty, s.ref.beauty);
        brightest          = testimg::brightest_energy_ratio(out, s.ref.beauty);
        std::printf("%s %d spp: frame mean %.3f (input %.3f), brightest 0.5%% %.3f\n",
                    std::get<0>(GetParam()), std::get<1>(GetParam()), mean_ratio,
                    input_mean_ratio, brightest);
    }
    double mean_ratio = 0, input_mean_ratio = 0, brightest = 0;
};

// The target, met everywhere: measured 0.982 (mirrors, 4 spp, whose
// input is itself 0.980) to 1.005. The clamp alone lost up to 12% (mirrors)
// and 9% (interior, dim) at 4 spp. And the frame mean is its input's:
// measured within 0.7%.
TEST_P(DenoiseEnergy, KeepsTheFrameMean)
{
    EXPECT_NEAR(mean_ratio, 1.0, 0.02);
    EXPECT_NEAR(mean_ratio, input_mean_ratio, 0.01);
}

// The target (90% of the brightest 0.5% of the reference's pixels)
// is met at 16 and 64 spp on every scene (lowest: dof 0.933 at 16 spp;
// metal, whose glints the clamp cut to 0.72, keeps 0.99). At 4 spp dof
// keeps 0.88 and metal 0.84: there the averaging, not the outlier step,
// flattens the defocused highlights and the sparsely sampled glints.
TEST_P(DenoiseEnergy, KeepsTheBrightestPixelsEnergy)
{
    EXPECT_GT(brightest, std::get<1>(GetParam()) >= 16 ? 0.9 : 0.8);
}

INSTANTIATE_TEST_SUITE_P(RefSet, DenoiseEnergy,
                         ::testing::Combine(::testing::ValuesIn(all_scenes),
                                            ::testing::Values(4, 16, 64)),
                         [](const auto& info) {
                             return std::string(std::get<0>(info.param)) + "_"
                                    + std::to_string(std::get<1>(info.param)) + "spp";
                         });

class DenoiseOnEveryScene : public ::testing::TestWithParam<const char*> {};

// Where the input is already good the filter must not make it worse:
// measured denoise / raw from 0.10 (cornell, 64 spp) to 0.86 (textured,
// 256 spp).
TEST_P(DenoiseOnEveryScene, IsNeverWorseThanItsInputAt64And256Spp)
{
    for (int spp : { 64, 256 }) {
        const SceneAt s(GetParam(), spp);
        EXPECT_LT(s.rel_mse(mcdenoise::denoise(s.noisy.beauty, s.noisy.guides())),
                  s.rel_mse(s.noisy.beauty))
            << spp << " spp";
    }
}

// At 16 spp below the raw 64-spp render on 7 of 8 scenes (measured 0.09 to
// 0.72 of it); textured is 2.0x (sub-pixel texture, docs/denoise.md).
TEST_P(DenoiseOnEveryScene, BeatsRaw64SppAt16SppOutsideTextured)
{
    const SceneAt s(GetParam(), 16), many(GetParam(), 64);
    const double denoised = s.rel_mse(mcdenoise::denoise(s.noisy.beauty, s.noisy.guides()));
    const double raw_64   = many.rel_mse(many.noisy.beauty);
    if (std::string(GetParam()) == "textured")
        EXPECT_LT(denoised, 2.5 * raw_64);
    else
        EXPECT_LT(denoised, raw_64);
}

// Against the previous preset (the clamp then nlmeans): the energy it kept
// is signal. Measured previous / denoise at 4, 16, 64 spp: interior 2.94,
// 1.21, 1.01; dim 2.02, 1.17, 1.18; mirrors 1.27, 1.03, 1.09; metal 0.69
// (4 spp: the glints' excess spread around them), 1.20, 1.19; the other
// scenes 0.98 to 1.11.
TEST_P(DenoiseOnEveryScene, IsNoWorseThanThePreviousPresetFrom16Spp)
{
    for (int spp : { 16, 64 }) {
        const SceneAt s(GetParam(), spp);
        EXPECT_LT(s.rel_mse(mcdenoise::denoise(s.noisy.beauty, s.noisy.guides())),
                  1.03 * s.rel_mse(previous_preset(s.noisy)))
            << spp << " spp";
    }
}

INSTANTIATE_TEST_SUITE_P(RefSet, DenoiseOnEveryScene, ::testing::ValuesIn(all_scenes));

TEST(DenoiseOnDarkInteriors, KeepsWhatTheClampLostAt4Spp)
{
    for (const char* scene : { "interior", "dim" }) {
        const SceneAt s(scene, 4);
        EXPECT_LT(s.rel_mse(mcdenoise::denoise(s.noisy.beauty, s.noisy.guides())),
                  0.6 * s.rel_mse(previous_preset(s.noisy)))
            << scene;
    }
}

}  // namespace
