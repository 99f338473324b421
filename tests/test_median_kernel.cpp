// test_median_kernel.cpp: the SIMD median networks (8 lanes, and 16 where
// the processor has AVX-512) against sorting, on random windows with many
// ties, for every size a network serves; and in-place selection.
#include "walkers/median_kernel.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

namespace {

using mcdenoise::MedianKernel;

// The median of the window of side k centered at column x of `plane` rows.
float sorted_median(const std::vector<std::vector<float>>& plane, int k, int x)
{
    std::vector<float> w;
    for (const auto& row : plane)
        for (int dx = -k / 2; dx <= k / 2; ++dx)
            w.push_back(row[size_t(x + dx)]);
    std::sort(w.begin(), w.end());
    return w[w.size() / 2];
}

void expect_kernel_matches_sorting(const MedianKernel& kernel, int k, uint32_t seed)
{
    ASSERT_NE(kernel.run, nullptr);
    std::mt19937 rng(seed);
    const int width = 64;
    for (int trial = 0; trial < 200; ++trial) {
        const int levels = trial % 2 ? 1000 : 4;  // few distinct values: many ties
        std::vector<std::vector<float>> plane(static_cast<size_t>(k), std::vector<float>(width));
        for (auto& row : plane)
            for (float& v : row)
                v = float(rng() % levels) - 2.5f;
        std::vector<const float*> rows;
        for (const auto& row : plane)
            rows.push_back(row.data());
        const int x = k / 2 + int(rng() % 8);
        float medians[16];
        kernel.run(rows.data(), x, medians);
        for (int l = 0; l < kernel.lanes; ++l)
            ASSERT_EQ(medians[l], sorted_median(plane, k, x + l))
                << "size " << k << " lanes " << kernel.lanes << " lane " << l;
    }
}

TEST(MedianKernel, NetworksMatchSortingForEverySize)
{
    for (int k : { 3, 5, 7, 9 }) {
        expect_kernel_matches_sorting(mcdenoise::narrow_median_kernel(k), k, 1);
        expect_kernel_matches_sorting(mcdenoise::wide_median_kernel(k), k, 2);
    }
}

TEST(MedianKernel, PrunedNetworkSizes)
{
    // Batcher's sort pruned to the median: far fewer than a full sort.
    EXPECT_EQ(mcdenoise::median_network_size(3), 24);
    EXPECT_EQ(mcdenoise::median_network_size(7), 319);
    EXPECT_EQ(mcdenoise::median_network_size(11), 0);
    EXPECT_EQ(mcdenoise::narrow_median_kernel(11).run, nullptr);
}

TEST(MedianKernel, InPlaceSelectionAveragesTheMiddlePairForEvenCounts)
{
    std::vector<float> odd { 5, 1, 4, 2, 3 };
    EXPECT_EQ(mcdenoise::median_in_place(odd.data(), 5), 3.0f);
    std::vector<float> even { 8, 1, 4, 2 };
    EXPECT_EQ(mcdenoise::median_in_place(even.data(), 4), 3.0f);
    std::vector<float> one { 7 };
    EXPECT_EQ(mcdenoise::median_in_place(one.data(), 1), 7.0f);
}

}  // namespace
