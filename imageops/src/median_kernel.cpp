// median_kernel.cpp: building pruned median networks, and generic selection.
#include "median_kernel.h"

#include <algorithm>
#include <array>
#include <memory>
#include <mutex>
#include <utility>

namespace mcdenoise {

float median_in_place(float* values, int n)
{
    const int upper = n / 2;
    std::nth_element(values, values + upper, values + n);
    if (n % 2 == 1)
        return values[upper];
    const float lower = *std::max_element(values, values + upper);
    return float(0.5 * (double(lower) + double(values[upper])));
}

namespace {

// Batcher's odd-even merge sort on `n` (a power of two) inputs: comparator
// (i, j) puts the smaller value in position i.
std::vector<std::pair<int, int>> batcher_sort(int n)
{
    std::vector<std::pair<int, int>> net;
    for (int p = 1; p < n; p *= 2)
        for (int k = p; k >= 1; k /= 2)
            for (int j = k % p; j + k < n; j += 2 * k)
                for (int i = 0; i < std::min(k, n - j - k); ++i)
                    if ((i + j) / (2 * p) == (i + j + k) / (2 * p))
                        net.emplace_back(i + j, i + j + k);
    return net;
}

}  // namespace

MedianNetwork::MedianNetwork(int count)
    : m_count(count)
{
    int padded = 1;
    while (padded < count)
        padded *= 2;
    constexpr int infinity = -1;  // a padding position: holds +inf
    const int scratch      = count;

    // Follow each sorted position to the slot holding its value; a
    // comparator against +inf is then a renaming or nothing at all.
    std::vector<int> slot_of(size_t(padded), infinity);
    for (int i = 0; i < count; ++i)
        slot_of[size_t(i)] = i;
    std::vector<std::pair<int, int>> live;  // (slot gets min, slot gets max)
    for (auto [i, j] : batcher_sort(padded)) {
        int& lo = slot_of[size_t(i)];
        int& hi = slot_of[size_t(j)];
        if (lo == infinity)
            std::swap(lo, hi);
        else if (hi != infinity)
            live.emplace_back(lo, hi);
    }
    m_result = slot_of[size_t((count - 1) / 2)];

    // Walk back from the median, keeping only what reaches it.
    std::vector<char> needed(size_t(count) + 1, 0);
    needed[size_t(m_result)] = 1;
    for (auto it = live.rbegin(); it != live.rend(); ++it) {
        const auto [lo, hi] = *it;
        const bool want_min = needed[size_t(lo)], want_max = needed[size_t(hi)];
        if (!want_min && !want_max)
            continue;
        m_ops.push_back({ lo, hi, want_min ? lo : scratch, want_max ? hi : scratch });
        needed[size_t(lo)] = needed[size_t(hi)] = 1;
    }
    std::reverse(m_ops.begin(), m_ops.end());
}

const MedianNetwork* MedianNetwork::for_count(int count)
{
    if (count < 1 || count > max_count || count % 2 == 0)
        return nullptr;
    static std::array<std::unique_ptr<MedianNetwork>, max_count + 1> cache;
    static std::mutex mutex;
    std::lock_guard<std::mutex> lock(mutex);
    auto& net = cache[size_t(count)];
    if (!net)
        net.reset(new MedianNetwork(count));
    return net.get();
}

}  // namespace mcdenoise
