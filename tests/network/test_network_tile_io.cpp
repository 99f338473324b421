// test_network_tile_io.cpp: a tile's pixels into the network's input tensor
// and back (network/tile_io.h): every encoding and the auxiliary images
// against formulas written plainly here, the channel order and the padded
// channels, zeros around the data (also over image pixels outside the
// tile's input), sanitising of NaN, negative and infinite values, the input
// scale both ways, round trips through an identity network on one tile and
// on a tiled plan, and the arguments refused.
#include "network/tile_io.h"
#include "network/transfer.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace mcdenoise;

const float nan = std::numeric_limits<float>::quiet_NaN();
const float inf = std::numeric_limits<float>::infinity();

/// Interleaved pixels, `channels` floats each, rows packed.
struct Image {
    int width, height, channels;
    std::vector<float> values;

    Image(int w, int h, int c = 3, float fill = 0.f)
        : width(w)
        , height(h)
        , channels(c)
        , values(size_t(w) * size_t(h) * size_t(c), fill)
    {
    }
    float* at(int x, int y)
    {
        return values.data() + (size_t(y) * size_t(width) + size_t(x)) * size_t(channels);
    }
    const float* at(int x, int y) const
    {
        return values.data() + (size_t(y) * size_t(width) + size_t(x)) * size_t(channels);
    }
    RgbIn in() const
    {
        return { values.data(), width, height, channels, std::ptrdiff_t(width) * channels };
    }
    RgbOut out()
    {
        return { values.data(), width, height, channels, std::ptrdiff_t(width) * channels };
    }
};

/// Values drawn log-uniformly from `lo` to `hi`.
Image random_image(int w, int h, int c, double lo, double hi, unsigned seed)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> e(std::log(lo), std::log(hi));
    Image im(w, h, c);
    for (float& v : im.values)
        v = float(std::exp(e(rng)));
    return im;
}

/// A planar CHW tensor of a tile.
struct Tensor {
    int width, height, channels;
    std::vector<float> values;

    Tensor(const Tile& tile, int c)
        : width(tile.tensor.width)
        , height(tile.tensor.height)
        , channels(c)
        , values(size_t(width) * size_t(height) * size_t(c), -7.f)
    {
    }
    float at(int c, int i, int j) const
    {
        return values[(size_t(c) * size_t(height) + size_t(j)) * size_t(width) + size_t(i)];
    }
    float& at(int c, int i, int j)
    {
        return values[(size_t(c) * size_t(height) + size_t(j)) * size_t(width) + size_t(i)];
    }
};

/// A tile reading `input` of an image into a tensor spanning `tensor`.
Tile tile_of(TileRect tensor, TileRect input, TileRect output) { return { tensor, input, output }; }

/// The whole of a `w` x `h` image as one tile, its tensor padded to 16.
Tile whole(int w, int h)
{
    return tile_of({ 0, 0, (w + 15) / 16 * 16, (h + 15) / 16 * 16 }, { 0, 0, w, h },
                   { 0, 0, w, h });
}

/// The main input's encoding, plainly: OIDN's getInput.
float encoded(float v, const NetworkInput& input)
{
    v *= input.input_scale;
    if (std::isnan(v))
        v = 0.f;
    switch (input.encoding) {
    case Encoding::hdr: return pu_forward(std::min(std::max(v, 0.f), FLT_MAX)) / pu_norm();
    case Encoding::ldr: return srgb_forward(std::min(std::max(v, 0.f), 1.f));
    case Encoding::srgb: return std::min(std::max(v, 0.f), 1.f);
    case Encoding::normal: return std::min(std::max(v, -1.f), 1.f) * 0.5f + 0.5f;
    }
    return -1.f;
}

/// The output's decoding, plainly: OIDN's output process.
float decoded(float v, const NetworkInput& input)
{
    if (std::isnan(v) || v < 0.f)
        v = 0.f;
    float out = v;
    if (input.encoding == Encoding::hdr)
        out = pu_inverse(v * pu_norm());
    else if (input.encoding == Encoding::ldr)
        out = std::min(srgb_inverse(v), 1.f);
    else if (input.encoding == Encoding::srgb)
        out = std::min(v, 1.f);
    else
        out = std::min(std::max(v * 2.f - 1.f, -1.f), 1.f);
    // A scale of 0 gives 0, also where the decoded value is infinite.
    return input.input_scale != 0.f ? out / input.input_scale : 0.f;
}

void expect_close(float actual, float expected, const std::string& what)
{
    EXPECT_NEAR(actual, expected, 2e-6f * std::max(1.f, std::abs(expected))) << what;
}

TEST(NetworkTileIo, InputChannels)
{
    EXPECT_EQ(input_channels({}), 3);
    EXPECT_EQ(input_channels({ Encoding::hdr, 1.f, true, false }), 6);
    EXPECT_EQ(input_channels({ Encoding::hdr, 1.f, true, true }), 9);
}

TEST(NetworkTileIo, ChannelOrderAndPaddedChannels)
{
    Image colour(5, 3), albedo(5, 3), normal(5, 3);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 5; ++x)
            for (int k = 0; k < 3; ++k) {
                colour.at(x, y)[k] = 0.1f * float(k + 1);
                albedo.at(x, y)[k] = 0.4f + 0.1f * float(k);
                normal.at(x, y)[k] = -0.5f + 0.5f * float(k);
            }
    const NetworkInput input { Encoding::srgb, 1.f, true, true };
    const Tile tile = whole(5, 3);
    Tensor t(tile, 16);
    ASSERT_TRUE(write_input_tile({ colour.in(), albedo.in(), normal.in() }, input, tile, 16,
                                 t.values.data()));
    float expected[9];
    for (int k = 0; k < 3; ++k) {
        expected[k]     = colour.at(0, 0)[k];
        expected[3 + k] = albedo.at(0, 0)[k];
        expected[6 + k] = normal.at(0, 0)[k] * 0.5f + 0.5f;
    }
    for (int c = 0; c < 16; ++c)
        for (int j = 0; j < 16; ++j)
            for (int i = 0; i < 16; ++i)
                EXPECT_EQ(t.at(c, i, j), c < 9 && i < 5 && j < 3 ? expected[c] : 0.f)
                    << "channel " << c << " at " << i << "," << j;
}

TEST(NetworkTileIo, EveryEncodingAgainstTheFormulas)
{
    Image colour = random_image(21, 13, 4, 1e-6, 1e5, 1);
    Image albedo = random_image(21, 13, 3, 1e-3, 2, 2);
    Image normal(21, 13);
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> signed_unit(-1.5f, 1.5f);
    for (float& v : normal.values)
        v = signed_unit(rng);
    // Some values to sanitise, in every image.
    const float odd[] = { nan, -2.f, inf, -inf, 0.f, FLT_MAX, 0.5f, -0.f };
    for (int k = 0; k < 8; ++k) {
        colour.at(k, 1)[k % 3] = odd[k];
        albedo.at(k, 2)[k % 3] = odd[k];
        normal.at(k, 3)[k % 3] = odd[k];
    }
    const Tile tile = whole(21, 13);
    for (Encoding e : { Encoding::hdr, Encoding::ldr, Encoding::srgb, Encoding::normal }) {
        for (float scale : { 1.f, 0.37f, 4.f }) {
            const NetworkInput input { e, scale, true, true };
            Tensor t(tile, 9);
            ASSERT_TRUE(write_input_tile({ colour.in(), albedo.in(), normal.in() }, input, tile, 9,
                                         t.values.data()));
            for (int y = 0; y < 13; ++y) {
                for (int x = 0; x < 21; ++x) {
                    for (int k = 0; k < 3; ++k) {
                        const std::string at = "encoding " + std::to_string(int(e)) + " scale "
                                               + std::to_string(scale) + " pixel "
                                               + std::to_string(x) + "," + std::to_string(y)
                                               + " channel " + std::to_string(k);
                        expect_close(t.at(k, x, y), encoded(colour.at(x, y)[k], input),
                                     "main " + at);
                        float a = albedo.at(x, y)[k];
                        a       = std::isnan(a) ? 0.f : std::min(std::max(a, 0.f), 1.f);
                        EXPECT_EQ(t.at(3 + k, x, y), a) << "albedo " << at;
                        float n = normal.at(x, y)[k];
                        n       = std::isnan(n) ? 0.f : std::min(std::max(n, -1.f), 1.f);
                        EXPECT_EQ(t.at(6 + k, x, y), n * 0.5f + 0.5f) << "normal " << at;
                    }
                }
            }
        }
    }
}

TEST(NetworkTileIo, SanitisedInputValues)
{
    Image colour(8, 1);
    const float in[8] = { nan, -2.f, inf, -inf, 0.f, FLT_MAX, 65504.f, 1.f };
    for (int x = 0; x < 8; ++x)
        colour.at(x, 0)[0] = in[x];
    const Tile tile = whole(8, 1);
    Tensor t(tile, 3);
    ASSERT_TRUE(write_input_tile({ colour.in(), {}, {} }, { Encoding::hdr, 1.f, false, false },
                                 tile, 3, t.values.data()));
    const float big         = pu_forward(FLT_MAX) / pu_norm();
    const float expected[8] = { 0.f, 0.f, big, 0.f, 0.f, big, 1.f, pu_forward(1.f) / pu_norm() };
    for (int x = 0; x < 8; ++x)
        EXPECT_NEAR(t.at(0, x, 0), expected[x], 1e-6f) << in[x];
    EXPECT_TRUE(std::isfinite(big));
    // A NaN scaled is NaN, an infinity scaled by 0 is NaN: both 0.
    ASSERT_TRUE(write_input_tile({ colour.in(), {}, {} }, { Encoding::hdr, 0.f, false, false },
                                 tile, 3, t.values.data()));
    for (int x = 0; x < 8; ++x)
        EXPECT_EQ(t.at(0, x, 0), 0.f) << in[x];
}

TEST(NetworkTileIo, ZerosAroundTheInputEvenOverImagePixels)
{
    // A tensor over image pixels (2..17, 1..16) of a 12x9 image reading
    // only (5..10, 3..7): the image pixels it spans outside that read as 0,
    // as OIDN pads a short last tile.
    Image colour(12, 9, 3, 0.25f);
    for (int y = 0; y < 9; ++y)
        for (int x = 0; x < 12; ++x)
            colour.at(x, y)[1] = 0.01f * float(x + 12 * y);
    const Tile tile = tile_of({ 2, 1, 16, 16 }, { 5, 3, 6, 5 }, { 6, 4, 3, 2 });
    const NetworkInput input { Encoding::ldr, 1.f, false, false };
    Tensor t(tile, 4);
    ASSERT_TRUE(write_input_tile({ colour.in(), {}, {} }, input, tile, 4, t.values.data()));
    for (int c = 0; c < 4; ++c)
        for (int j = 0; j < 16; ++j)
            for (int i = 0; i < 16; ++i) {
                const int x = 2 + i, y = 1 + j;
                const bool read = c < 3 && x >= 5 && x < 11 && y >= 3 && y < 8;
                EXPECT_EQ(t.at(c, i, j), read ? srgb_forward(colour.at(x, y)[c]) : 0.f)
                    << "channel " << c << " tensor " << i << "," << j;
            }
}

TEST(NetworkTileIo, OutputDecodingAgainstTheFormulas)
{
    // A 1-row tensor of network outputs, every odd value among them.
    const float values[] = { nan,  -1.f,  0.f, 1e-5f, 2e-3f, 0.03f, 0.2f, 0.37f,
                             0.5f, 0.75f, 1.f, 1.5f,  2.f,   40.f,  inf,  FLT_MAX };
    const int n          = int(sizeof(values) / sizeof(values[0]));
    const Tile tile      = tile_of({ 0, 0, n, 1 }, { 0, 0, n, 1 }, { 0, 0, n, 1 });
    Tensor t(tile, 3);
    for (int c = 0; c < 3; ++c)
        for (int i = 0; i < n; ++i)
            t.at(c, i, 0) = values[(i + c) % n];
    for (Encoding e : { Encoding::hdr, Encoding::ldr, Encoding::srgb, Encoding::normal }) {
        for (float scale : { 1.f, 0.25f, 3.f, 0.f }) {
            const NetworkInput input { e, scale, false, false };
            Image out(n, 1, 4, 42.f);
            ASSERT_TRUE(read_output_tile(t.values.data(), input, tile, out.out()));
            for (int i = 0; i < n; ++i) {
                for (int c = 0; c < 3; ++c) {
                    const float expected   = decoded(values[(i + c) % n], input);
                    const float actual     = out.at(i, 0)[c];
                    const std::string what = "encoding " + std::to_string(int(e)) + " scale "
                                             + std::to_string(scale) + " value "
                                             + std::to_string(values[(i + c) % n]);
                    if (std::isinf(expected))
                        EXPECT_EQ(actual, expected) << what;
                    else
                        EXPECT_NEAR(actual, expected, 2e-6f * std::max(1.f, std::abs(expected)))
                            << what;
                    EXPECT_FALSE(std::isnan(actual)) << what;
                }
                EXPECT_EQ(out.at(i, 0)[3], 42.f) << "alpha untouched";
            }
        }
    }
}

TEST(NetworkTileIo, HdrOutputHasNoUpperClamp)
{
    const Tile tile = tile_of({ 0, 0, 16, 16 }, { 0, 0, 1, 1 }, { 0, 0, 1, 1 });
    Tensor t(tile, 3);
    t.at(0, 0, 0) = 1.5f;
    t.at(1, 0, 0) = 1.f;
    t.at(2, 0, 0) = 0.9f;
    Image out(1, 1);
    ASSERT_TRUE(
        read_output_tile(t.values.data(), { Encoding::hdr, 0.5f, false, false }, tile, out.out()));
    EXPECT_GT(out.at(0, 0)[0], 65504.f * 2.f);
    EXPECT_NEAR(out.at(0, 0)[1], 65504.f * 2.f, 65504.f * 2.f * 1e-5f);
    EXPECT_LT(out.at(0, 0)[2], 65504.f * 2.f);
}

TEST(NetworkTileIo, OnlyTheOutputRectangleIsWritten)
{
    const Tile tile = tile_of({ 10, 20, 32, 16 }, { 10, 20, 30, 12 }, { 14, 22, 7, 5 });
    Tensor t(tile, 3);
    for (int c = 0; c < 3; ++c)
        for (int j = 0; j < 16; ++j)
            for (int i = 0; i < 32; ++i)
                t.at(c, i, j) = 0.001f * float(i + 100 * j) + 0.1f * float(c);
    Image out(50, 40, 3, -3.f);
    ASSERT_TRUE(
        read_output_tile(t.values.data(), { Encoding::srgb, 1.f, false, false }, tile, out.out()));
    for (int y = 0; y < 40; ++y)
        for (int x = 0; x < 50; ++x)
            for (int c = 0; c < 3; ++c) {
                const bool written   = x >= 14 && x < 21 && y >= 22 && y < 27;
                const float expected = written ? std::min(t.at(c, x - 10, y - 20), 1.f) : -3.f;
                EXPECT_EQ(out.at(x, y)[c], expected) << x << "," << y << " channel " << c;
            }
}

/// Writes every tile of `plan` for `image`, passes its first three planes
/// through as the network's output, and reads each tile's output back.
Image through_identity(const TilePlan& plan, const Image& image, const NetworkInput& input)
{
    Image out(image.width, image.height, 3, -1.f);
    for (const Tile& tile : plan.tiles) {
        Tensor t(tile, 16);
        EXPECT_TRUE(write_input_tile({ image.in(), {}, {} }, input, tile, 16, t.values.data()));
        EXPECT_TRUE(read_output_tile(t.values.data(), input, tile, out.out()));
    }
    return out;
}

TEST(NetworkTileIo, RoundTripThroughAnIdentityNetwork)
{
    Image hdr       = random_image(1000, 40, 3, 1e-6, 6e4, 5);
    hdr.at(3, 3)[0] = nan;
    hdr.at(4, 3)[1] = -5.f;
    TilePlan one, tiled;
    std::string error;
    ASSERT_TRUE(plan_tiles(1000, 40, 96, 1LL << 40, one, error)) << error;
    ASSERT_TRUE(plan_tiles(1000, 40, 96, 800 * 48, tiled, error)) << error;
    ASSERT_EQ(one.tiles.size(), 1u);
    ASSERT_GT(tiled.tiles.size(), 1u);
    for (const TilePlan* plan : { &one, &tiled }) {
        for (float scale : { 1.f, 0.125f }) {
            const NetworkInput input { Encoding::hdr, scale, false, false };
            const Image out = through_identity(*plan, hdr, input);
            for (int y = 0; y < 40; ++y)
                for (int x = 0; x < 1000; ++x)
                    for (int k = 0; k < 3; ++k) {
                        float v = hdr.at(x, y)[k];
                        v       = std::isnan(v) || v < 0.f ? 0.f : v;
                        EXPECT_NEAR(out.at(x, y)[k], v, 1e-5f * v + 1e-12f)
                            << x << "," << y << " scale " << scale << " tiles "
                            << plan->tiles.size();
                    }
        }
    }
    // LDR and sRGB: within [0, 1]; the clamped values come back clamped.
    Image ldr = random_image(1000, 40, 3, 1e-4, 2, 6);
    for (Encoding e : { Encoding::ldr, Encoding::srgb }) {
        const Image out = through_identity(tiled, ldr, { e, 1.f, false, false });
        for (size_t i = 0; i < ldr.values.size(); ++i)
            EXPECT_NEAR(out.values[i], std::min(ldr.values[i], 1.f), 1e-5f * ldr.values[i]);
    }
    Image normal(1000, 40);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> signed_unit(-1.f, 1.f);
    for (float& v : normal.values)
        v = signed_unit(rng);
    const Image out = through_identity(tiled, normal, { Encoding::normal, 1.f, false, false });
    for (size_t i = 0; i < normal.values.size(); ++i)
        EXPECT_NEAR(out.values[i], normal.values[i], 1.2e-7f);
}

TEST(NetworkTileIo, RefusesInvalidArguments)
{
    Image colour(8, 8), small(4, 8);
    const Tile tile = whole(8, 8);
    Tensor t(tile, 9);
    float* dst = t.values.data();
    const NetworkInput plain {};
    const NetworkInput with_albedo { Encoding::hdr, 1.f, true, false };
    const NetworkInput normal_only { Encoding::hdr, 1.f, false, true };
    const NetworkInput both { Encoding::hdr, 1.f, true, true };
    EXPECT_FALSE(write_input_tile({}, plain, tile, 3, dst));
    EXPECT_FALSE(write_input_tile({ colour.in(), {}, {} }, plain, tile, 3, nullptr));
    EXPECT_FALSE(write_input_tile({ colour.in(), {}, {} }, with_albedo, tile, 6, dst));
    EXPECT_FALSE(write_input_tile({ colour.in(), small.in(), {} }, with_albedo, tile, 6, dst));
    EXPECT_FALSE(write_input_tile({ colour.in(), {}, colour.in() }, normal_only, tile, 6, dst));
    EXPECT_FALSE(write_input_tile({ colour.in(), colour.in(), colour.in() }, both, tile, 8, dst));
    EXPECT_FALSE(write_input_tile({ colour.in(), {}, {} }, plain,
                                  tile_of({ 0, 0, 16, 16 }, { 0, 0, 9, 8 }, {}), 3, dst));
    EXPECT_FALSE(write_input_tile({ colour.in(), {}, {} }, plain,
                                  tile_of({ 1, 0, 16, 16 }, { 0, 0, 8, 8 }, {}), 3, dst));
    EXPECT_FALSE(write_input_tile({ colour.in(), {}, {} }, plain,
                                  tile_of({ 0, 0, 16, 16 }, { 0, 0, 0, 8 }, {}), 3, dst));
    for (float v : t.values)
        ASSERT_EQ(v, -7.f) << "written by a refused call";
    EXPECT_TRUE(write_input_tile({ colour.in(), colour.in(), colour.in() }, both, tile, 9, dst));
    Image out(8, 8);
    EXPECT_FALSE(read_output_tile(dst, plain, tile, RgbOut {}));
    EXPECT_FALSE(read_output_tile(nullptr, plain, tile, out.out()));
    EXPECT_FALSE(
        read_output_tile(dst, plain, tile_of({ 0, 0, 16, 16 }, {}, { 0, 0, 9, 8 }), out.out()));
    EXPECT_FALSE(
        read_output_tile(dst, plain, tile_of({ 1, 0, 16, 16 }, {}, { 0, 0, 8, 8 }), out.out()));
    EXPECT_FALSE(
        read_output_tile(dst, plain, tile_of({ 0, 0, 16, 16 }, {}, { 0, 0, 8, 0 }), out.out()));
    EXPECT_TRUE(read_output_tile(dst, plain, tile, out.out()));
}

}  // namespace
