// test_weighted_sums.cpp: WeightedSums::add_rows, the weighted sums of many
// weight rows in one pass, against the same rows added one at a time and
// against sums in double precision; and the masked values both masked
// layouts hold (interleaved and planar), against the rule written out.
#include "features/weighted_sums.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace {

using mcdenoise::PixelBlock;
using mcdenoise::SumSource;
using mcdenoise::WeightedSums;
using mcdenoise::WeightRow;

/// `nc` planes of random values over `region`, some not finite when
/// `masked` (then with their finite mask).
SumSource random_source(const OIIO::ROI& region, int nc, bool masked, std::mt19937& rng)
{
    std::uniform_real_distribution<float> value(-2.0f, 5.0f);
    SumSource src(region, nc);
    for (auto& plane : src.values)
        for (float& v : plane)
            v = value(rng);
    if (masked) {
        src.finite = SumSource(region, nc, 1.0f).values;
        for (int c = 0; c < nc; ++c)
            for (size_t i = 3; i < src.values[size_t(c)].size(); i += 7) {
                src.values[size_t(c)][i]  = 0.0f;  // a non-finite value as sums take it
                src.finite[size_t(c)][i] = 0.0f;
            }
    }
    return src;
}

}  // namespace

TEST(WeightedSums, AddRowsIsAddRowByRowAndTheWeightedMean)
{
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> weight(0.0f, 1.0f);
    const OIIO::ROI region(0, 60, 0, 4);
    const int n = 37, x0 = 11;  // a run that ends in a partial block of lanes
    for (const bool masked : { false, true })
        for (const int nc : { 1, 5, 14 }) {  // one group, one group, two groups
            const SumSource src = random_source(region, nc, masked, rng);
            // One search row: offsets dx in [-5, 5] at source row 2; the
            // outer ones cover only part of the run, as at an image edge.
            std::vector<std::vector<float>> w;
            std::vector<WeightRow> rows;
            for (int dx = -5; dx <= 5; ++dx) {
                w.emplace_back(size_t(n));
                for (float& v : w.back())
                    v = weight(rng);
                const int i0 = dx == -5 ? 9 : 0, i1 = dx == 5 ? n - 17 : n;
                rows.push_back({ w.back().data(), x0 + dx, 2, i0, i1 });
            }
            WeightedSums batched(0, nc, n, masked), single(0, nc, n, masked);
            batched.add_rows(rows.data(), int(rows.size()), src);
            for (const WeightRow& r : rows)
                single.add(r.w, src, r.qx0, r.qy, r.i0, r.i1);
            std::vector<float> a(size_t(n * nc)), b(size_t(n * nc));
            batched.write(a.data(), nc);
            single.write(b.data(), nc);
            for (int i = 0; i < n; ++i)
                for (int c = 0; c < nc; ++c) {
                    const float got = a[size_t(i * nc + c)];
                    EXPECT_EQ(got, b[size_t(i * nc + c)]) << masked << " " << nc << " " << i;
                    double num = 0.0, den = 0.0;
                    for (const WeightRow& r : rows) {
                        if (i < r.i0 || i >= r.i1)
                            continue;
                        const double m = masked ? *src.finite_from(c, r.qx0 + i, 2) : 1.0;
                        num += double(r.w[i]) * m * *src.from(c, r.qx0 + i, 2);
                        den += double(r.w[i]) * m;
                    }
                    EXPECT_NEAR(got, num / den, 1e-5 * (1.0 + std::abs(num / den)));
                }
        }
}

TEST(WeightedSums, BothMaskedLayoutsHoldTheOneMaskedValueRule)
{
    // Each input with the value and the weight a masked sum takes from it:
    // non-finite values as 0 with weight 0, magnitudes beyond 2^100 clamped.
    struct Case {
        float in, value, weight;
    };
    const float inf = std::numeric_limits<float>::infinity();
    const Case cases[] = {
        { 1.5f, 1.5f, 1.0f },          { -0.25f, -0.25f, 1.0f },
        { 0.0f, 0.0f, 1.0f },          { std::nanf(""), 0.0f, 0.0f },
        { inf, 0.0f, 0.0f },           { -inf, 0.0f, 0.0f },
        { 3e30f, 0x1p100f, 1.0f },     { -1e38f, -0x1p100f, 1.0f },
        { 0x1p100f, 0x1p100f, 1.0f },  { 1e29f, 1e29f, 1.0f },
        { 7.0f, 7.0f, 1.0f },
    };
    const int ncases = int(std::size(cases));
    const int nc = 3;
    const OIIO::ROI region(2, 7, 1, 4, 0, 1, 0, nc);
    PixelBlock block;
    block.region     = region;
    block.nchannels  = nc;
    block.row_stride = std::ptrdiff_t(region.width()) * nc;
    block.owned.resize(size_t(region.width() * region.height() * nc));
    block.data = block.owned.data();
    // Case k at value k (mod the count): every case lands in every channel.
    for (size_t k = 0; k < block.owned.size(); ++k)
        block.owned[k] = cases[k % size_t(ncases)].in;

    const PixelBlock interleaved = mcdenoise::with_finite_mask(block, 1);
    const SumSource planar       = mcdenoise::sum_source(block, 0, nc, region, 1);
    ASSERT_EQ(interleaved.nchannels, 2 * nc);
    ASSERT_TRUE(planar.masked());
    for (int y = region.ybegin; y < region.yend; ++y)
        for (int x = region.xbegin; x < region.xend; ++x)
            for (int c = 0; c < nc; ++c) {
                const size_t k = size_t(block.pixel(x, y) - block.data) + size_t(c);
                const Case& want = cases[k % size_t(ncases)];
                const float* mixed = interleaved.pixel(x, y);
                const float value = *planar.from(c, x, y), weight = *planar.finite_from(c, x, y);
                EXPECT_EQ(mixed[c], value) << x << "," << y << " channel " << c;
                EXPECT_EQ(mixed[nc + c], weight) << x << "," << y << " channel " << c;
                EXPECT_EQ(value, want.value) << "input " << want.in;
                EXPECT_EQ(weight, want.weight) << "input " << want.in;
            }
}
