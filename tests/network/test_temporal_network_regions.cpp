// test_temporal_network_regions.cpp: the network's cross-frame denoise
// (denoise_network of NetworkFrames) where a shot's motion makes it hard,
// on the shot set's testrender shots at 16 spp: the pixels a camera move
// uncovers (shot_truck) and those a moving sphere and its shadow leave
// behind (shot_object) are no worse than the network frame by frame
// (relMSE within 1.1x: no ghost, no trail), and every frame is better.
// FAILS when the weights are missing: run scripts/fetch-weights.
#include "support/render_file.h"
#include "support/shot.h"

#include <mcdenoise/mcdenoise.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

using OIIO::ImageBuf;

std::string dir() { return testimg::shotset_dir(MCD_SHOTSET_DIR_DEFAULT); }

mcdenoise::NetworkOptions options()
{
    mcdenoise::NetworkOptions o;
    const char* weights = std::getenv("MCD_WEIGHTS_DIR");
    o.weights_dir       = weights && *weights ? weights : MCD_WEIGHTS_DIR_DEFAULT;
    return o;
}

/// Every frame of `shot` made once (`prepare_network_frame`, with motion).
std::vector<mcdenoise::NetworkFrame> network_frames(const testimg::Shot& shot)
{
    std::vector<mcdenoise::NetworkFrame> frames;
    for (int t = shot.first; t <= shot.last(); ++t)
        frames.push_back(mcdenoise::prepare_network_frame(shot.input(t, true), options()));
    return frames;
}

/// Frame `t` across its neighbours within `n` frames.
ImageBuf across(const testimg::Shot& shot, const std::vector<mcdenoise::NetworkFrame>& frames, int t,
                int n)
{
    std::vector<mcdenoise::NetworkFrame> neighbours;
    std::vector<int> offsets;
    for (int u : shot.neighbours(t, n)) {
        neighbours.push_back(frames[size_t(u - shot.first)]);
        offsets.push_back(u - t);
    }
    return mcdenoise::denoise_network(frames[size_t(t - shot.first)], neighbours, offsets);
}

/// relMSE of `a` against `ref` over every pixel (colour).
double rel_mse(const ImageBuf& a, const ImageBuf& ref)
{
    return mcdenoise::compare_images(a, ref).rel_mse;
}

TEST(TemporalNetworkRegions, CameraMoveUncoversNoGhost)
{
    const testimg::Shot shot = testimg::read_shot(dir(), "shot_truck", 0, 6);
    ASSERT_TRUE(shot.error.empty()) << shot.error;
    const std::vector<mcdenoise::NetworkFrame> frames = network_frames(shot);
    for (int t = 2; t <= 4; ++t) {
        std::string error;
        const ImageBuf ref = testimg::read_beauty(dir() + "/shot_truck_ref_f" + std::to_string(t) + ".exr", error);
        ASSERT_TRUE(error.empty()) << error;
        const ImageBuf out = across(shot, frames, t, 2);
        ASSERT_FALSE(out.has_error()) << out.geterror();
        const ImageBuf& own  = *frames[size_t(t)].denoised;
        const ImageBuf mask  = testimg::disoccluded_pixels(shot, t);
        const double region  = testimg::masked_rel_mse(out, ref, mask);
        const double alone   = testimg::masked_rel_mse(own, ref, mask);
        std::printf("frame %d: uncovered pixels %.3fx, frame %.3fx the per-frame network\n", t,
                    region / alone, rel_mse(out, ref) / rel_mse(own, ref));
        EXPECT_LE(region, 1.1 * alone) << "frame " << t << ": uncovered pixels";
        EXPECT_LT(rel_mse(out, ref), rel_mse(own, ref)) << "frame " << t;
    }
}

TEST(TemporalNetworkRegions, MovingObjectLeavesNoTrail)
{
    const testimg::Shot shot = testimg::read_shot(dir(), "shot_object", 0, 4);
    ASSERT_TRUE(shot.error.empty()) << shot.error;
    std::string error;
    const ImageBuf ref = testimg::read_beauty(dir() + "/shot_object_ref_f2.exr", error);
    std::vector<ImageBuf> others;
    for (int t : { 0, 1, 3, 4 })
        others.push_back(testimg::read_beauty(dir() + "/shot_object_256_f" + std::to_string(t) + ".exr", error));
    ASSERT_TRUE(error.empty()) << error;
    const std::vector<mcdenoise::NetworkFrame> frames = network_frames(shot);
    const ImageBuf out = across(shot, frames, 2, 2);
    ASSERT_FALSE(out.has_error()) << out.geterror();
    const ImageBuf& own = *frames[2].denoised;
    // The moving sphere's id (shots.cpp).
    const ImageBuf mask = testimg::left_behind_pixels(shot, 2, 20.0f, ref, others);
    const double left = testimg::masked_rel_mse(out, ref, mask), alone = testimg::masked_rel_mse(own, ref, mask);
    std::printf("left-behind pixels %.3fx, frame %.3fx the per-frame network\n", left / alone,
                rel_mse(out, ref) / rel_mse(own, ref));
    EXPECT_LE(left, 1.1 * alone) << "where the sphere and its shadow were";
    EXPECT_LT(rel_mse(out, ref), rel_mse(own, ref));
}

}  // namespace
