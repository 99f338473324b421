// test_refset.cpp: checks on the cached reference set (CTest fixture
// `refset`): every file is there with its metadata, and each scene's relMSE
// against its reference falls as 1/spp (4x the samples, ~1/4 the error).
#include <mcdenoise/metrics.h>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

std::string refset_dir()
{
    const char* dir = std::getenv("MCD_REFSET_DIR");
    return dir ? dir : MCD_REFSET_DIR_DEFAULT;
}

/// The beauty (R, G, B) of a reference-set file, and its spp from metadata.
OIIO::ImageBuf beauty(const std::string& file, int& spp)
{
    OIIO::ImageBuf all(refset_dir() + "/" + file);
    if (!all.read(0, 0, true, OIIO::TypeDesc::FLOAT)) {
        ADD_FAILURE() << file << ": " << all.geterror();
        return {};
    }
    spp = all.spec().get_int_attribute("testrender:spp", 0);
    const int channels[] = { all.spec().channelindex("R"), all.spec().channelindex("G"),
                             all.spec().channelindex("B") };
    return OIIO::ImageBufAlgo::channels(all, 3, channels);
}

class RefSet : public ::testing::TestWithParam<const char*> {};

// relMSE(n) = V / n + V / n_ref for a reference of n_ref samples (independent
// seed; the renderer is unbiased), so the expected ratio for 4 -> 16 spp is
// 4 (1 + 4/n_ref) / (1 + 16/n_ref) = 3.97 and for 16 -> 32 spp 1.98 with
// n_ref = 2048. Measured at 128x128 over seeds 1..6 and the five scenes
// (docs/testrender.md) the ratios were 3.27..5.01 and 1.85..2.15: caustic paths
// (light seen through mirrors and glass, found only by BSDF sampling) are
// heavy-tailed, and a single firefly moves the 4-spp error. The bands below
// hold that spread with a margin; a biased renderer (error plateaus, ratio
// -> 1) or correlated samples (ratio far from 4) falls outside them.
constexpr double min_ratio_4_to_16 = 2.5, max_ratio_4_to_16 = 6.5;
constexpr double min_ratio_16_to_32 = 1.5, max_ratio_16_to_32 = 2.7;

TEST_P(RefSet, RelMseFallsAsOneOverSpp)
{
    const std::string scene = GetParam();
    int ref_spp = 0;
    const OIIO::ImageBuf ref = beauty(scene + "_ref.exr", ref_spp);
    ASSERT_GE(ref_spp, 1024) << "reference of " << scene << " has too few samples";
    double rel[3];
    const int spps[3] = { 4, 16, 32 };
    for (int i = 0; i < 3; ++i) {
        int spp = 0;
        const OIIO::ImageBuf img = beauty(scene + "_" + std::to_string(spps[i]) + ".exr", spp);
        ASSERT_EQ(spp, spps[i]);
        const mcdenoise::ImageComparison c = mcdenoise::compare_images(img, ref);
        ASSERT_TRUE(c.ok) << c.error;
        EXPECT_EQ(c.nonfinite, 0);
        rel[i] = c.rel_mse;
        std::printf("%-9s %2d spp: relMSE %.5f  PSNR %.2f dB  SSIM %.4f\n", scene.c_str(),
                    spps[i], c.rel_mse, c.psnr, c.ssim);
    }
    const double r1 = rel[0] / rel[1], r2 = rel[1] / rel[2];
    std::printf("%-9s ratios: 4->16 %.2f, 16->32 %.2f (reference %d spp)\n", scene.c_str(), r1,
                r2, ref_spp);
    EXPECT_GT(r1, min_ratio_4_to_16);
    EXPECT_LT(r1, max_ratio_4_to_16);
    EXPECT_GT(r2, min_ratio_16_to_32);
    EXPECT_LT(r2, max_ratio_16_to_32);
}

INSTANTIATE_TEST_SUITE_P(Scenes, RefSet,
                         ::testing::Values("cornell", "mirrors", "textured", "dof", "interior"));

}  // namespace
