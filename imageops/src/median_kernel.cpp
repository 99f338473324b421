// median_kernel.cpp: the unrolled SIMD median networks and in-place selection.
#include "median_kernel.h"

#include "median_network.h"

#include <OpenImageIO/simd.h>

#include <algorithm>
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

using OIIO::simd::vfloat8;

template<int K>
struct WindowNet {
    static constexpr auto net = network::build_median_net<K * K>();
};

template<int K, size_t... I>
inline void run_ops(vfloat8* v, std::index_sequence<I...>)
{
    constexpr auto& net = WindowNet<K>::net;
    auto step = [v](const network::Op& op) {
        const vfloat8 a = v[op.a], b = v[op.b];
        v[op.to_min] = OIIO::simd::min(a, b);
        v[op.to_max] = OIIO::simd::max(a, b);
    };
    (step(net.ops[I]), ...);
}

template<int K>
void window_median8_k(const float* const* rows, float* medians)
{
    constexpr int r = K / 2;
    vfloat8 v[K * K + 1];
    for (int dy = 0; dy < K; ++dy)
        for (int dx = 0; dx < K; ++dx)
            v[dy * K + dx].load(rows[dy] + dx - r);
    run_ops<K>(v, std::make_index_sequence<size_t(WindowNet<K>::net.count)>());
    v[WindowNet<K>::net.result].store(medians);
}

}  // namespace

WindowMedian8 window_median8(int size)
{
    switch (size) {
    case 3: return window_median8_k<3>;
    case 5: return window_median8_k<5>;
    case 7: return window_median8_k<7>;
    case 9: return window_median8_k<9>;
    default: return nullptr;
    }
}

int median_network_size(int size)
{
    switch (size) {
    case 3: return WindowNet<3>::net.count;
    case 5: return WindowNet<5>::net.count;
    case 7: return WindowNet<7>::net.count;
    case 9: return WindowNet<9>::net.count;
    default: return 0;
    }
}

}  // namespace mcdenoise
