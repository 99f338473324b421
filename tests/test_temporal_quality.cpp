// test_temporal_quality.cpp: the cross-frame denoise on the shot set's
// testrender shots at 16 spp (make_shot_set), against per-frame `denoise`
// and the warped-average baseline. Thresholds from the measurements in
// docs/temporal.md (bench/temporal_table), with a little room.
#include "support/shot.h"
#include "support/shot_figures.h"

#include <gtest/gtest.h>

namespace {

std::string dir() { return testimg::shotset_dir(MCD_SHOTSET_DIR_DEFAULT); }

}  // namespace

TEST(TemporalQuality, StaticShotN3)
{
    const testimg::ShotFigures f = testimg::static_figures(dir());
    ASSERT_TRUE(f.error.empty()) << f.error;
    // measured: relMSE 0.33x, flicker 0.11x of per-frame; baseline 0.42x, 0.07x
    EXPECT_LT(f.cross.rel_mse, 0.36 * f.per_frame.rel_mse);
    EXPECT_LT(f.cross.flicker, 0.13 * f.per_frame.flicker);
    EXPECT_LT(f.cross.rel_mse, f.baseline.rel_mse);
    for (size_t i = 0; i < f.evaluated.size(); ++i)
        EXPECT_LT(f.cross.frame_rel_mse[i], f.per_frame.frame_rel_mse[i]) << "frame " << i;
}

TEST(TemporalQuality, CameraMoveN2WithMotion)
{
    const testimg::ShotFigures f = testimg::truck_figures(dir());
    ASSERT_TRUE(f.error.empty()) << f.error;
    // measured: relMSE 0.60x, temporal error 0.59x, disoccluded 0.66x of per-frame
    EXPECT_LT(f.cross.rel_mse, 0.63 * f.per_frame.rel_mse);
    EXPECT_LT(f.cross.temporal, 0.62 * f.per_frame.temporal);
    EXPECT_LT(f.cross.region, 1.1 * f.per_frame.region) << "disoccluded pixels";
    for (size_t i = 0; i < f.evaluated.size(); ++i)
        EXPECT_LT(f.cross.frame_rel_mse[i], f.per_frame.frame_rel_mse[i])
            << "frame " << f.evaluated[i];
    EXPECT_LT(f.cross.rel_mse, f.baseline.rel_mse);
    EXPECT_LT(f.cross.temporal, f.baseline.temporal);
    // the motion guide is what carries the neighbours: without it, less gain
    EXPECT_LT(f.cross.rel_mse, f.cross_still.rel_mse);
}

TEST(TemporalQuality, MovingObjectLeavesNoGhost)
{
    const testimg::ShotFigures f = testimg::object_figures(dir());
    ASSERT_TRUE(f.error.empty()) << f.error;
    // measured: left-behind region 0.67x of per-frame, the baseline's 9.0x
    EXPECT_LE(f.cross.region, f.per_frame.region) << "ghost where the object and shadow were";
    EXPECT_LT(f.cross.region, f.baseline.region);
    EXPECT_LT(f.cross.rel_mse, f.per_frame.rel_mse);
    EXPECT_LT(f.cross.rel_mse, f.baseline.rel_mse);
}
