// median_kernel.cpp: the unrolled SIMD median networks (GCC vector types, an
// AVX-512 build of the 16-lane kernels picked at run time) and in-place
// selection.
#include "walkers/median_kernel.h"

#include "walkers/median_network.h"

#include <algorithm>
#include <cstring>
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

#define MCD_INLINE inline __attribute__((always_inline))

// GCC vector types (a dependent vector_size in an alias template is
// ignored, so each width is spelled out).
typedef float Vec8 __attribute__((vector_size(8 * sizeof(float))));
typedef float Vec16 __attribute__((vector_size(16 * sizeof(float))));
template<int Lanes>
struct VecOf;
template<>
struct VecOf<8> {
    using type = Vec8;
};
template<>
struct VecOf<16> {
    using type = Vec16;
};
template<int Lanes>
using Vec = typename VecOf<Lanes>::type;
static_assert(sizeof(Vec<8>) == 8 * sizeof(float) && sizeof(Vec<16>) == 16 * sizeof(float));

template<int K>
struct WindowNet {
    static constexpr auto net = network::build_median_net<K * K>();
};

template<int Lanes>
MCD_INLINE void compare_exchange(Vec<Lanes>* v, const network::Op& op)
{
    const Vec<Lanes> a = v[op.a], b = v[op.b];
    const auto less    = a < b;
    v[op.to_min]       = less ? a : b;
    v[op.to_max]       = less ? b : a;
}

template<int K, int Lanes, size_t... I>
MCD_INLINE void run_ops(Vec<Lanes>* v, std::index_sequence<I...>)
{
    constexpr auto& net = WindowNet<K>::net;
    (compare_exchange<Lanes>(v, net.ops[I]), ...);
}

template<int K, int Lanes>
MCD_INLINE void window_medians(const float* const* rows, int x, float* medians)
{
    constexpr int r = K / 2;
    Vec<Lanes> v[K * K + 1];
    for (int dy = 0; dy < K; ++dy)
        for (int dx = 0; dx < K; ++dx)
            std::memcpy(&v[dy * K + dx], rows[dy] + x + dx - r, sizeof(Vec<Lanes>));
    run_ops<K, Lanes>(v, std::make_index_sequence<size_t(WindowNet<K>::net.count)>());
    std::memcpy(medians, &v[WindowNet<K>::net.result], sizeof(Vec<Lanes>));
}

template<int K>
void slot_medians8(const float* slots, float* medians)
{
    Vec<8> v[K * K + 1];
    std::memcpy(v, slots, sizeof(Vec<8>) * K * K);
    run_ops<K, 8>(v, std::make_index_sequence<size_t(WindowNet<K>::net.count)>());
    std::memcpy(medians, &v[WindowNet<K>::net.result], sizeof(Vec<8>));
}

template<int K>
void medians8(const float* const* rows, int x, float* medians)
{
    window_medians<K, 8>(rows, x, medians);
}

template<int K>
__attribute__((target("avx512f"))) void medians16(const float* const* rows, int x,
                                                  float* medians)
{
    window_medians<K, 16>(rows, x, medians);
}

bool has_avx512()
{
    static const bool yes = __builtin_cpu_supports("avx512f");
    return yes;
}

}  // namespace

MedianKernel narrow_median_kernel(int size)
{
    switch (size) {
    case 3: return { medians8<3>, 8 };
    case 5: return { medians8<5>, 8 };
    case 7: return { medians8<7>, 8 };
    case 9: return { medians8<9>, 8 };
    default: return {};
    }
}

MedianKernel wide_median_kernel(int size)
{
    if (!has_avx512())
        return narrow_median_kernel(size);
    switch (size) {
    case 3: return { medians16<3>, 16 };
    case 5: return { medians16<5>, 16 };
    case 7: return { medians16<7>, 16 };
    case 9: return { medians16<9>, 16 };
    default: return {};
    }
}

SlotMedians slot_median_kernel(int size)
{
    switch (size) {
    case 3: return slot_medians8<3>;
    case 5: return slot_medians8<5>;
    case 7: return slot_medians8<7>;
    case 9: return slot_medians8<9>;
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
