// test_network_tiling.cpp: the tile plan (network/tiling.h): for many image
// sizes, overlaps and budgets, the outputs partition the image (per side,
// and pixel by pixel on the smaller images), each tile reads its output
// plus the overlap but at the image's edges, sizes and data are aligned to
// 16, the budget is kept unless the tiles are at their smallest; one tile
// when the padded image fits; and two plans worked out by hand from OIDN's
// UNetFilter::init and execute.
#include "network/tiling.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace mcdenoise;

TilePlan plan_of(int w, int h, int overlap, long long budget)
{
    TilePlan plan;
    std::string error;
    EXPECT_TRUE(plan_tiles(w, h, overlap, budget, plan, error)) << error;
    return plan;
}

std::string name(int w, int h, int overlap, long long budget)
{
    return std::to_string(w) + "x" + std::to_string(h) + " overlap " + std::to_string(overlap)
           + " budget " + std::to_string(budget);
}

bool contains(const TileRect& outer, const TileRect& r)
{
    return r.x >= outer.x && r.y >= outer.y && r.x + r.width <= outer.x + outer.width
           && r.y + r.height <= outer.y + outer.height;
}

/// Every property a plan of a `w` x `h` image must have.
void check_plan(int w, int h, int overlap, long long budget)
{
    SCOPED_TRACE(name(w, h, overlap, budget));
    const TilePlan plan = plan_of(w, h, overlap, budget);
    ASSERT_GE(plan.rows, 1);
    ASSERT_GE(plan.columns, 1);
    ASSERT_EQ(plan.tiles.size(), size_t(plan.rows) * size_t(plan.columns));
    EXPECT_EQ(plan.tile_width % 16, 0);
    EXPECT_EQ(plan.tile_height % 16, 0);
    EXPECT_LE(plan.tile_width, padded_size(w));
    EXPECT_LE(plan.tile_height, padded_size(h));
    const int min_side = min_tile_side(overlap);
    EXPECT_TRUE(1LL * plan.tile_width * plan.tile_height <= budget
                || (plan.tile_width <= min_side && plan.tile_height <= min_side));
    if (1LL * padded_size(w) * padded_size(h) <= budget) {
        EXPECT_EQ(plan.tiles.size(), 1u);
    }
    const TileRect image { 0, 0, w, h };
    for (int i = 0; i < plan.rows; ++i) {
        for (int j = 0; j < plan.columns; ++j) {
            SCOPED_TRACE("tile " + std::to_string(i) + "," + std::to_string(j));
            const Tile& t = plan.tiles[size_t(i * plan.columns + j)];
            // The outputs form a grid: a row of tiles shares its rows, a
            // column its columns, and they abut from edge to edge.
            const Tile& first_in_row    = plan.tiles[size_t(i * plan.columns)];
            const Tile& first_in_column = plan.tiles[size_t(j)];
            EXPECT_EQ(t.output.y, first_in_row.output.y);
            EXPECT_EQ(t.output.height, first_in_row.output.height);
            EXPECT_EQ(t.output.x, first_in_column.output.x);
            EXPECT_EQ(t.output.width, first_in_column.output.width);
            EXPECT_GT(t.output.width, 0);
            EXPECT_GT(t.output.height, 0);
            const TileRect& left = plan.tiles[size_t(i * plan.columns + std::max(j - 1, 0))].output;
            const TileRect& above =
                plan.tiles[size_t(std::max(i - 1, 0) * plan.columns + j)].output;
            EXPECT_EQ(t.output.x, j == 0 ? 0 : left.x + left.width);
            EXPECT_EQ(t.output.y, i == 0 ? 0 : above.y + above.height);
            if (j == plan.columns - 1) {
                EXPECT_EQ(t.output.x + t.output.width, w);
            }
            if (i == plan.rows - 1) {
                EXPECT_EQ(t.output.y + t.output.height, h);
            }
            // The tensor: the plan's size, aligned, past the image only to
            // the right and below, by less than the alignment.
            EXPECT_EQ(t.tensor.width, plan.tile_width);
            EXPECT_EQ(t.tensor.height, plan.tile_height);
            EXPECT_EQ(t.tensor.x % 16, 0);
            EXPECT_EQ(t.tensor.y % 16, 0);
            EXPECT_GE(t.tensor.x, 0);
            EXPECT_GE(t.tensor.y, 0);
            EXPECT_LT(t.tensor.x + t.tensor.width - w, 16);
            EXPECT_LT(t.tensor.y + t.tensor.height - h, 16);
            // The input: inside the image and the tensor, starting aligned
            // in the tensor, covering the output plus the overlap.
            EXPECT_TRUE(contains(image, t.input));
            EXPECT_TRUE(contains(t.tensor, t.input));
            EXPECT_TRUE(contains(t.input, t.output));
            EXPECT_EQ((t.input.x - t.tensor.x) % 16, 0);
            EXPECT_EQ((t.input.y - t.tensor.y) % 16, 0);
            const int x0 = std::max(t.output.x - overlap, 0);
            const int y0 = std::max(t.output.y - overlap, 0);
            const int x1 = std::min(t.output.x + t.output.width + overlap, w);
            const int y1 = std::min(t.output.y + t.output.height + overlap, h);
            EXPECT_TRUE(contains(t.input, { x0, y0, x1 - x0, y1 - y0 }));
        }
    }
}

/// Every pixel of the image written by exactly one tile.
void check_partition_pixelwise(int w, int h, int overlap, long long budget)
{
    SCOPED_TRACE(name(w, h, overlap, budget));
    const TilePlan plan = plan_of(w, h, overlap, budget);
    std::vector<unsigned char> writes(size_t(w) * size_t(h), 0);
    for (const Tile& t : plan.tiles)
        for (int y = t.output.y; y < t.output.y + t.output.height; ++y)
            for (int x = t.output.x; x < t.output.x + t.output.width; ++x)
                if (x >= 0 && x < w && y >= 0 && y < h)
                    ++writes[size_t(y) * size_t(w) + size_t(x)];
                else
                    ADD_FAILURE() << "pixel " << x << "," << y << " outside the image";
    EXPECT_EQ(std::count(writes.begin(), writes.end(), 1), std::ptrdiff_t(writes.size()));
}

TEST(NetworkTiling, PaddedSizeAndMinimumSide)
{
    EXPECT_EQ(padded_size(1), 16);
    EXPECT_EQ(padded_size(16), 16);
    EXPECT_EQ(padded_size(17), 32);
    EXPECT_EQ(padded_size(1080), 1088);
    EXPECT_EQ(padded_size(1 << 30), 1 << 30);
    EXPECT_EQ(min_tile_side(0), 768);
    EXPECT_EQ(min_tile_side(96), 768);
    EXPECT_EQ(min_tile_side(112), 768);
    EXPECT_EQ(min_tile_side(208), 832);
}

TEST(NetworkTiling, OneTileWhenThePaddedImageFits)
{
    for (const auto& s :
         { std::pair<int, int> { 1, 1 }, { 17, 33 }, { 1920, 1080 }, { 4000, 15 } }) {
        const TilePlan plan =
            plan_of(s.first, s.second, 96, 1LL * padded_size(s.first) * padded_size(s.second));
        ASSERT_EQ(plan.tiles.size(), 1u);
        const Tile& t = plan.tiles[0];
        EXPECT_EQ(plan.tile_width, padded_size(s.first));
        EXPECT_EQ(plan.tile_height, padded_size(s.second));
        const int tensor[] = { t.tensor.x, t.tensor.y, t.tensor.width, t.tensor.height };
        const int whole[]  = { 0, 0, s.first, s.second };
        const int input[]  = { t.input.x, t.input.y, t.input.width, t.input.height };
        const int output[] = { t.output.x, t.output.y, t.output.width, t.output.height };
        EXPECT_EQ(tensor[2], plan.tile_width);
        EXPECT_EQ(tensor[3], plan.tile_height);
        EXPECT_EQ(tensor[0], 0);
        EXPECT_EQ(tensor[1], 0);
        EXPECT_TRUE(std::equal(input, input + 4, whole));
        EXPECT_TRUE(std::equal(output, output + 4, whole));
    }
}

TEST(NetworkTiling, UhdSplitInTwoAsOidnDoes)
{
    // 3840x2160 under OIDN's default cap of 2160^2 pixels: padded
    // 3840x2160 is too big; the height is not taller, so the width is cut:
    // ceil((3840 + 192) / 2) = 2016 wide, ceil((3840 - 192) / (2016 - 192))
    // = 2 tiles, inputs from 0 and 1824, outputs 0-1920 and 1920-3840.
    const TilePlan plan = plan_of(3840, 2160, 96, 2160LL * 2160);
    ASSERT_EQ(plan.columns, 2);
    ASSERT_EQ(plan.rows, 1);
    EXPECT_EQ(plan.tile_width, 2016);
    EXPECT_EQ(plan.tile_height, 2160);
    const Tile& a = plan.tiles[0];
    const Tile& b = plan.tiles[1];
    EXPECT_EQ(a.input.x, 0);
    EXPECT_EQ(a.input.width, 2016);
    EXPECT_EQ(a.output.x, 0);
    EXPECT_EQ(a.output.width, 1920);
    EXPECT_EQ(b.input.x, 1824);
    EXPECT_EQ(b.input.width, 2016);
    EXPECT_EQ(b.tensor.x, 1824);
    EXPECT_EQ(b.output.x, 1920);
    EXPECT_EQ(b.output.width, 1920);
}

TEST(NetworkTiling, ShortLastTileIsAlignedToTheTensorsEnd)
{
    // 2000x16 with at most 16000 pixels a tile: 1104 wide is too many, then
    // ceil((2000 + 2 * 192) / 3) = 795, aligned 800, ceil(1808 / 608) = 3
    // tiles; inputs from 0, 608, 1216; the last reads 784 columns, placed
    // 16 columns into its tensor, which starts at 1200.
    const TilePlan plan = plan_of(2000, 16, 96, 16000);
    ASSERT_EQ(plan.columns, 3);
    ASSERT_EQ(plan.rows, 1);
    EXPECT_EQ(plan.tile_width, 800);
    EXPECT_EQ(plan.tile_height, 16);
    const int input_x[]      = { 0, 608, 1216 };
    const int input_width[]  = { 800, 800, 784 };
    const int tensor_x[]     = { 0, 608, 1200 };
    const int output_x[]     = { 0, 704, 1312 };
    const int output_width[] = { 704, 608, 688 };
    for (int j = 0; j < 3; ++j) {
        const Tile& t = plan.tiles[size_t(j)];
        EXPECT_EQ(t.input.x, input_x[j]) << j;
        EXPECT_EQ(t.input.width, input_width[j]) << j;
        EXPECT_EQ(t.tensor.x, tensor_x[j]) << j;
        EXPECT_EQ(t.output.x, output_x[j]) << j;
        EXPECT_EQ(t.output.width, output_width[j]) << j;
        EXPECT_EQ(t.tensor.y, 0);
        EXPECT_EQ(t.input.height, 16);
        EXPECT_EQ(t.output.height, 16);
    }
}

TEST(NetworkTiling, PropertiesHoldForManySizesAndBudgets)
{
    std::vector<std::pair<int, int>> sizes = { { 1, 1 },       { 16, 16 },     { 767, 769 },
                                               { 768, 768 },   { 1000, 900 },  { 1920, 1080 },
                                               { 3840, 2160 }, { 7680, 4320 }, { 5000, 3 },
                                               { 3, 5000 },    { 2049, 2047 } };
    std::mt19937 rng(46);
    std::uniform_int_distribution<int> side(1, 6000);
    for (int i = 0; i < 60; ++i)
        sizes.push_back({ side(rng), side(rng) });
    const long long budgets[] = { 1LL << 40, 2160LL * 2160, 1000000, 768LL * 768, 500000, 1 };
    for (const auto& s : sizes)
        for (int overlap : { 0, 96, 112, 256 })
            for (long long budget : budgets)
                check_plan(s.first, s.second, overlap, budget);
}

TEST(NetworkTiling, OutputsPartitionTheImagePixelByPixel)
{
    const int sizes[][2] = { { 1, 1 },     { 17, 33 },    { 1000, 900 },  { 1600, 800 },
                             { 2000, 16 }, { 800, 1999 }, { 2500, 1700 }, { 1537, 1535 } };
    for (const auto& s : sizes)
        for (int overlap : { 0, 96, 112 })
            for (long long budget : { 1LL << 40, 1000000LL, 600000LL, 1LL })
                check_partition_pixelwise(s[0], s[1], overlap, budget);
}

TEST(NetworkTiling, RefusesInvalidArguments)
{
    TilePlan plan;
    plan.rows = 7;
    std::string error;
    EXPECT_FALSE(plan_tiles(0, 10, 96, 1000, plan, error));
    EXPECT_NE(error.find("image size"), std::string::npos) << error;
    EXPECT_FALSE(plan_tiles(10, -1, 96, 1000, plan, error));
    EXPECT_FALSE(plan_tiles(10, (1 << 30) + 1, 96, 1000, plan, error));
    EXPECT_FALSE(plan_tiles(10, 10, 90, 1000, plan, error));
    EXPECT_NE(error.find("overlap"), std::string::npos) << error;
    EXPECT_FALSE(plan_tiles(10, 10, -16, 1000, plan, error));
    EXPECT_FALSE(plan_tiles(10, 10, 96, 0, plan, error));
    EXPECT_NE(error.find("maximum tile size"), std::string::npos) << error;
    EXPECT_EQ(plan.rows, 7);
    EXPECT_TRUE(plan.tiles.empty());
}

}  // namespace
