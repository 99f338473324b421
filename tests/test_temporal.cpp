// test_temporal.cpp: the cross-frame denoise on small hand-checkable
// sequences: no neighbours is `denoise`, a still noiseless shot stays
// as it is, a shifted shot averages the pixels its motion points at (chained
// over two frames, a missing frame's vector repeated) or that the search
// finds without motion, another surface in a neighbour gets no weight, a
// firefly's excess is shared by the frames that show its surface, the
// result is the same for any thread count, ROI split and neighbour order,
// and frames prepared once give it too.
#include <mcdenoise/mcdenoise.h>

#include "support/guide_images.h"
#include "support/test_images.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

using OIIO::ImageBuf;
using OIIO::ROI;
using OIIO::TypeDesc;
namespace mcd = mcdenoise;

namespace {

constexpr int width = 24, height = 20;

ImageBuf image(int nchannels, const std::vector<float>& values)
{
    return testimg::from_values(width, height, nchannels, TypeDesc::FLOAT, 0, 0, values);
}

ImageBuf constant(int nchannels, float v)
{
    return image(nchannels, std::vector<float>(size_t(width) * height * nchannels, v));
}

// One frame of a shot whose content sits `shift` columns to the right of
// frame 0's: the beauty is `colour(u, y)` of the content column u, the
// albedo a code unique to each content pixel (so no two pixels of one frame
// look alike and only the same content pixel matches across frames), the
// depth `depth(u, y)`, a large variance (every patch distance 0).
struct ShiftedFrame {
    ImageBuf beauty, albedo, depth, variance, motion;
    mcd::FrameInput input() const
    {
        mcd::FrameInput f { &beauty, {} };
        f.guides.albedo   = &albedo;
        f.guides.depth    = &depth;
        f.guides.variance = &variance;
        f.guides.motion   = motion.initialized() ? &motion : nullptr;
        return f;
    }
};

template<class Colour, class Depth>
ShiftedFrame shifted_frame(int shift, float back, float on, Colour&& colour, Depth&& depth)
{
    std::vector<float> c, a, z, m;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const int u = x - shift;
            for (int k = 0; k < 3; ++k)
                c.push_back(colour(u, y) + 0.01f * float(k));
            a.insert(a.end(), { 5.0f * float(u), 5.0f * float(y), 0.0f });
            z.push_back(depth(u, y));
            // Cycles' Vector: (x + X, y - Y) in the previous frame,
            // (x - Z, y + W) in the next.
            m.insert(m.end(), { back, 0.0f, -on, 0.0f });
        }
    return { image(3, c), image(3, a), image(1, z), constant(3, 100.0f), image(4, m) };
}

float colour_a(int u, int y) { return 0.5f + 0.01f * float((u * 7 + y * 13) % 11); }
float colour_b(int u, int y) { return 0.45f + 0.01f * float((u * 5 + y * 3) % 7); }
float unit_depth(int, int) { return 1.0f; }

float at(const ImageBuf& img, int x, int y, int c)
{
    float v[4] = {};
    img.getpixel(x, y, v, 4);
    return v[c];
}

// `count` frames of random RGBA noise with wavy normals and random motion
// of up to 2 pixels, each frame from its own seeds (`seed` + frame).
struct RandomShot {
    std::vector<ImageBuf> beauty, normal, motion;
    RandomShot(int count, int seed)
    {
        for (int f = 0; f < count; ++f) {
            beauty.push_back(testimg::random_image(width, height, 4, seed + f));
            normal.push_back(testimg::wavy_normals(width, height, seed + 10 + f));
            motion.push_back(testimg::random_image(width, height, 4, seed + 20 + f, -2.0f, 2.0f));
        }
    }
    mcd::FrameInput input(int f) const
    {
        mcd::FrameInput frame { &beauty[f], {} };
        frame.guides.normal = &normal[f];
        frame.guides.motion = &motion[f];
        return frame;
    }
};

// A flat grey frame (0.5) with one pixel at `peak`, a large measured
// variance (every patch distance 0, the peak's excess over the firefly
// bound 1.0 a known firefly) and a flat albedo.
struct PeakFrame {
    ImageBuf beauty, variance, albedo;
    PeakFrame(float peak, float albedo_value)
        : beauty(constant(3, 0.5f)), variance(constant(3, 1.0f)), albedo(constant(3, albedo_value))
    {
        const float p[3] = { peak, peak, peak };
        beauty.setpixel(width / 2, height / 2, p, 3);
    }
    mcd::FrameInput input() const
    {
        mcd::FrameInput f { &beauty, {} };
        f.guides.variance = &variance;
        f.guides.albedo   = &albedo;
        return f;
    }
};

// Each channel of `with` less `without`, summed over the frame.
std::vector<double> channel_gain(const ImageBuf& with, const ImageBuf& without)
{
    const std::vector<float> a = testimg::pixels(with), b = testimg::pixels(without);
    std::vector<double> gain(3, 0.0);
    for (size_t i = 0; i < a.size(); ++i)
        gain[i % 3] += double(a[i]) - double(b[i]);
    return gain;
}

// What a firefly of 2.5 in the frame at `firefly_offset` (0: the centre)
// adds to the centre's result of a shot of three frames (offsets -1, 0,
// 1): the result with it less the result with the peak at 1.0, at or
// below the firefly bound (the same clamped frames, so the same average).
// The centre's albedo is `centre_albedo`, the neighbours' 0.5.
std::vector<double> shot_gain(int firefly_offset, float centre_albedo)
{
    const auto result = [&](float peak) {
        const PeakFrame before(firefly_offset == -1 ? peak : 1.0f, 0.5f),
            centre(firefly_offset == 0 ? peak : 1.0f, centre_albedo),
            after(firefly_offset == 1 ? peak : 1.0f, 0.5f);
        return mcd::denoise(centre.input(), { before.input(), after.input() }, { -1, 1 });
    };
    return channel_gain(result(2.5f), result(1.0f));
}

// The same for the frame denoised alone: its whole excess.
std::vector<double> single_gain()
{
    const PeakFrame with(2.5f, 0.5f), without(1.0f, 0.5f);
    return channel_gain(mcd::denoise(with.beauty, with.input().guides),
                        mcd::denoise(without.beauty, without.input().guides));
}

}  // namespace

TEST(Temporal, NoNeighboursIsDenoise)
{
    const ImageBuf beauty = testimg::random_image(width, height, 4, 3);
    const ImageBuf normal = testimg::wavy_normals(width, height, 4);
    mcd::FrameInput centre { &beauty, {} };
    centre.guides.normal = &normal;
    const ImageBuf single   = mcd::denoise(beauty, centre.guides);
    const ImageBuf temporal = mcd::denoise(centre, {}, {});
    ASSERT_FALSE(temporal.has_error()) << temporal.geterror();
    EXPECT_TRUE(testimg::bit_identical(single, temporal));
}

TEST(Temporal, StillNoiselessShotStays)
{
    // A step edge with a tiny variance: only equal pixels weigh anything.
    std::vector<float> v;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            v.insert(v.end(), 3, x < width / 2 ? 0.3f : 0.6f);
    const ImageBuf beauty = image(3, v), variance = constant(1, 1e-6f);
    mcd::FrameInput frame { &beauty, {} };
    frame.guides.variance = &variance;
    const ImageBuf out = mcd::denoise(frame, { frame, frame }, { -1, 1 });
    ASSERT_FALSE(out.has_error()) << out.geterror();
    const std::vector<float> got = testimg::pixels(out);
    ASSERT_EQ(got.size(), v.size());
    for (size_t i = 0; i < v.size(); ++i)  // sums of equal values, rounded
        EXPECT_NEAR(got[i], v[i], 1e-5f) << i;
}

TEST(Temporal, MotionPicksTheMovedPixels)
{
    // Frame -1 shows the content 1 column left, frame -2 3 columns left:
    // the centre's vector X = -1, frame -1's X = -2, chained to -3.
    const ShiftedFrame centre = shifted_frame(0, -1.0f, 0.0f, colour_a, unit_depth);
    const ShiftedFrame prev   = shifted_frame(-1, -2.0f, 0.0f, colour_b, unit_depth);
    const ShiftedFrame prev2  = shifted_frame(-3, 0.0f, 0.0f,
                                             [](int u, int y) { return colour_a(u + 5, y); },
                                             unit_depth);
    const ImageBuf out = mcd::denoise(centre.input(), { prev.input(), prev2.input() }, { -1, -2 });
    ASSERT_FALSE(out.has_error()) << out.geterror();
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < 3; ++c) {
                // The content column x shows in frame -1 at x - 1, in -2 at x - 3.
                float sum = colour_a(x, y), n = 1.0f;
                if (x - 1 >= 0) {
                    sum += colour_b(x, y);
                    n += 1.0f;
                }
                if (x - 3 >= 0) {
                    sum += colour_a(x + 5, y);
                    n += 1.0f;
                }
                EXPECT_NEAR(at(out, x, y, c), sum / n + 0.01f * float(c), 1e-5f)
                    << x << "," << y << "," << c;
            }
}

TEST(Temporal, AMissingFrameRepeatsTheLastVector)
{
    // Two columns a frame; frame -1 is left out, so the centre's vector
    // (X = -2) stands in for it: frame -2 is read 4 columns left.
    const ShiftedFrame centre = shifted_frame(0, -2.0f, 0.0f, colour_a, unit_depth);
    const ShiftedFrame prev2  = shifted_frame(-4, 0.0f, 0.0f, colour_b, unit_depth);
    const ImageBuf out = mcd::denoise(centre.input(), { prev2.input() }, { -2 });
    ASSERT_FALSE(out.has_error()) << out.geterror();
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const float expected = x >= 4 ? (colour_a(x, y) + colour_b(x, y)) / 2 : colour_a(x, y);
            EXPECT_NEAR(at(out, x, y, 0), expected, 1e-5f) << x << "," << y;
        }
}

TEST(Temporal, WithoutMotionTheSearchFindsTheMovedPixels)
{
    // No motion guide: frame +1 shows the content 3 columns right, inside
    // the wider search window of a frame taken as it is.
    ShiftedFrame centre = shifted_frame(0, 0.0f, 0.0f, colour_a, unit_depth);
    ShiftedFrame next   = shifted_frame(3, 0.0f, 0.0f, colour_b, unit_depth);
    centre.motion.reset();
    next.motion.reset();
    const ImageBuf out = mcd::denoise(centre.input(), { next.input() }, { 1 });
    ASSERT_FALSE(out.has_error()) << out.geterror();
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const float expected =
                x + 3 < width ? (colour_a(x, y) + colour_b(x, y)) / 2 : colour_a(x, y);
            EXPECT_NEAR(at(out, x, y, 0), expected, 1e-5f) << x << "," << y;
        }
}

TEST(Temporal, WrongMotionFindsNothing)
{
    // The motion points the other way: the search window (radius 2) holds
    // no pixel with the centre's albedo, so the centre stays as it is.
    const ShiftedFrame centre = shifted_frame(0, 3.0f, 0.0f, colour_a, unit_depth);
    const ShiftedFrame prev   = shifted_frame(-3, 0.0f, 0.0f, colour_b, unit_depth);
    const ImageBuf out = mcd::denoise(centre.input(), { prev.input() }, { -1 });
    ASSERT_FALSE(out.has_error()) << out.geterror();
    EXPECT_TRUE(testimg::bit_identical(out, centre.beauty)) << "no weight from frame -1";
}

TEST(Temporal, AFireflysExcessIsSharedByTheFramesThatShowItsSurface)
{
    // The frames match everywhere (weight 1 each): the excess a frame
    // alone gives back is shared by the three, wherever the firefly is.
    const std::vector<double> whole = single_gain();
    ASSERT_GT(whole[0], 1.0);  // 2.5 less a bound near 1
    for (int offset : { -1, 0, 1 }) {
        const std::vector<double> shared = shot_gain(offset, 0.5f);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(shared[c], whole[c] / 3.0, 1e-4) << offset;
    }
    // Neighbours on another surface (albedo 0.5 against 2: a feature
    // weight near exp(-3 (1.5 / 0.3)^2 / 2)) leave the centre's excess to
    // the centre.
    const std::vector<double> kept = shot_gain(0, 2.0f);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(kept[c], whole[c], 1e-4);
}

TEST(Temporal, AnotherSurfaceGetsNoWeight)
{
    // Frame +1 has the same content and colour code but, right of column
    // 12, a surface three times as far: only the left part averages.
    const ShiftedFrame centre = shifted_frame(0, 0.0f, 0.0f, colour_a, unit_depth);
    const ShiftedFrame next   = shifted_frame(0, 0.0f, 0.0f, colour_b,
                                            [](int u, int) { return u > 12 ? 3.0f : 1.0f; });
    const ImageBuf out = mcd::denoise(centre.input(), { next.input() }, { 1 });
    ASSERT_FALSE(out.has_error()) << out.geterror();
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const float expected = x > 12 ? colour_a(x, y) : (colour_a(x, y) + colour_b(x, y)) / 2;
            EXPECT_NEAR(at(out, x, y, 0), expected, 1e-5f) << x << "," << y;
        }
}

TEST(Temporal, SameForAnyThreadsSplitAndOrder)
{
    const RandomShot shot(3, 10);
    const std::vector<mcd::FrameInput> frames { shot.input(0), shot.input(1), shot.input(2) };
    const ImageBuf one = mcd::denoise(frames[1], { frames[0], frames[2] }, { -1, 1 }, {}, 1);
    ASSERT_FALSE(one.has_error()) << one.geterror();
    EXPECT_TRUE(testimg::bit_identical(
        one, mcd::denoise(frames[1], { frames[0], frames[2] }, { -1, 1 }, {}, 2)));
    EXPECT_TRUE(testimg::bit_identical(
        one, mcd::denoise(frames[1], { frames[2], frames[0] }, { 1, -1 }, {}, 0)));
    ImageBuf split;
    const ROI top(0, width, 0, height / 2, 0, 1, 0, 4), bottom(0, width, height / 2, height, 0, 1, 0, 4);
    ASSERT_TRUE(mcd::denoise(split, frames[1], { frames[0], frames[2] }, { -1, 1 }, top, 1));
    const ImageBuf rest = mcd::denoise(frames[1], { frames[0], frames[2] }, { -1, 1 }, bottom, 2);
    EXPECT_EQ(testimg::pixels(split, top), testimg::pixels(one, top));
    EXPECT_EQ(testimg::pixels(rest, bottom), testimg::pixels(one, bottom));
}

TEST(Temporal, PreparedFramesGiveTheSameResult)
{
    // A shot of four frames, each prepared once and used in every window
    // it is in, as the centre and as a neighbour; a NaN in one frame
    // (a finite mask on its values only).
    RandomShot shot(4, 70);
    const float nan[4] = { std::nanf(""), 0.5f, 0.5f, 1.0f };
    shot.beauty[2].setpixel(5, 6, nan);
    std::vector<mcd::FrameInput> frames;
    std::vector<mcd::PreparedFrame> prepared;
    for (int f = 0; f < 4; ++f) {
        frames.push_back(shot.input(f));
        prepared.push_back(mcd::prepare_frame(frames.back(), 1 + f % 2));
        ASSERT_TRUE(prepared.back().data) << prepared.back().error;
    }
    for (int c = 1; c < 3; ++c) {
        const ImageBuf given = mcd::denoise(frames[c], { frames[c - 1], frames[c + 1] }, { -1, 1 });
        const ImageBuf from_prepared = mcd::denoise(prepared[c], { prepared[c + 1], prepared[c - 1] },
                                                    { 1, -1 }, {}, 2);
        ASSERT_FALSE(from_prepared.has_error()) << from_prepared.geterror();
        EXPECT_TRUE(testimg::bit_identical(given, from_prepared)) << "centre " << c;
    }
    const ROI corner(3, 14, 2, 9, 0, 1, 0, 4);
    EXPECT_EQ(testimg::pixels(mcd::denoise(prepared[1], { prepared[0] }, { -1 }, corner), corner),
              testimg::pixels(mcd::denoise(frames[1], { frames[0] }, { -1 }), corner));
    // An unprepared frame, or one whose preparation failed, is named.
    const mcd::PreparedFrame failed = mcd::prepare_frame({}, 0);
    EXPECT_FALSE(failed.data);
    EXPECT_NE(failed.error.find("no beauty"), std::string::npos);
    EXPECT_NE(mcd::denoise(prepared[1], { failed }, { 1 }).geterror().find("offset 1"),
              std::string::npos);
    EXPECT_NE(mcd::denoise(mcd::PreparedFrame(), {}, {}).geterror().find("centre frame: not prepared"),
              std::string::npos);
}

TEST(Temporal, TallFramesAreTheSameAsStripsOfRows)
{
    // Frames taller than the rows the average takes at a time: the whole
    // frame in one call equals strips of 40 rows each filtered alone (one
    // band each), with a NaN in a neighbour (finite masks).
    constexpr int w = 12, h = 300;
    std::vector<ImageBuf> beauty, motion;
    for (int f = 0; f < 3; ++f) {
        beauty.push_back(testimg::random_image(w, h, 3, 110 + f));
        motion.push_back(testimg::random_image(w, h, 4, 120 + f, -2.0f, 2.0f));
    }
    const float nan[3] = { std::nanf(""), 0.5f, 0.5f };
    beauty[0].setpixel(4, 130, nan);
    std::vector<mcd::PreparedFrame> frames;
    for (int f = 0; f < 3; ++f) {
        mcd::FrameInput in { &beauty[f], {} };
        in.guides.motion = &motion[f];
        frames.push_back(mcd::prepare_frame(in));
    }
    const ImageBuf whole = mcd::denoise(frames[1], { frames[0], frames[2] }, { -1, 1 });
    ASSERT_FALSE(whole.has_error()) << whole.geterror();
    for (int y = 0; y < h; y += 40) {
        const ROI strip(0, w, y, std::min(h, y + 40), 0, 1, 0, 3);
        EXPECT_EQ(testimg::pixels(mcd::denoise(frames[1], { frames[0], frames[2] }, { -1, 1 }, strip), strip),
                  testimg::pixels(whole, strip)) << "rows from " << y;
    }
}

TEST(Temporal, DataWindowOriginAndInPlace)
{
    // A data window away from the origin: the same result as at the
    // origin, moved; and `dst` may be the centre's beauty.
    const auto frames_at = [](int x0, int y0, std::vector<ImageBuf>& b, std::vector<ImageBuf>& m) {
        for (int f = 0; f < 3; ++f) {
            b.push_back(testimg::random_image(width, height, 3, 50 + f, 0.0f, 1.0f,
                                              TypeDesc::FLOAT, x0, y0));
            m.push_back(testimg::random_image(width, height, 4, 60 + f, -1.5f, 1.5f,
                                              TypeDesc::FLOAT, x0, y0));
        }
    };
    std::vector<ImageBuf> b0, m0, b1, m1;
    frames_at(0, 0, b0, m0);
    frames_at(7, -5, b1, m1);
    const auto input = [](std::vector<ImageBuf>& b, std::vector<ImageBuf>& m, int f) {
        mcd::FrameInput in { &b[size_t(f)], {} };
        in.guides.motion = &m[size_t(f)];
        return in;
    };
    const ImageBuf at_origin = mcd::denoise(input(b0, m0, 1), { input(b0, m0, 0), input(b0, m0, 2) },
                                            { -1, 1 });
    ImageBuf& in_place = b1[1];
    ASSERT_TRUE(mcd::denoise(in_place, input(b1, m1, 1), { input(b1, m1, 0), input(b1, m1, 2) },
                             { -1, 1 }));
    EXPECT_EQ(in_place.roi(), ROI(7, 7 + width, -5, -5 + height, 0, 1, 0, 3));
    EXPECT_EQ(testimg::pixels(in_place), testimg::pixels(at_origin));
}

TEST(Temporal, BadNeighboursAreNamed)
{
    const ImageBuf beauty = testimg::random_image(width, height, 3, 1);
    const ImageBuf small  = testimg::random_image(width - 1, height, 3, 2);
    const ImageBuf normal = testimg::wavy_normals(width, height, 3);
    const ImageBuf motion2 = testimg::random_image(width, height, 2, 4);
    const mcd::FrameInput centre { &beauty, {} };
    mcd::FrameInput with_normal { &beauty, {} };
    with_normal.guides.normal = &normal;
    mcd::FrameInput bad_motion { &beauty, {} };
    bad_motion.guides.motion = &motion2;
    const auto error = [&](const mcd::FrameInput& c, const std::vector<mcd::FrameInput>& n,
                           const std::vector<int>& o) {
        ImageBuf dst;
        EXPECT_FALSE(mcd::denoise(dst, c, n, o));
        EXPECT_FALSE(dst.initialized());
        return dst.geterror();
    };
    EXPECT_NE(error(centre, { { &small, {} } }, { 1 }).find("offset 1: data window"),
              std::string::npos);
    EXPECT_NE(error(centre, { with_normal }, { -2 }).find("offset -2: has not the centre"),
              std::string::npos);
    EXPECT_NE(error(centre, { centre, centre }, { 1, 1 }).find("distinct"), std::string::npos);
    EXPECT_NE(error(centre, { centre }, { 0 }).find("non-zero"), std::string::npos);
    EXPECT_NE(error(centre, { centre }, {}).find("1 neighbour frames but 0 offsets"),
              std::string::npos);
    EXPECT_NE(error(bad_motion, { bad_motion }, { 1 }).find("motion"), std::string::npos);
    EXPECT_NE(error({}, {}, {}).find("no beauty"), std::string::npos);
}
