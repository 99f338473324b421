// median_network.h: compile-time construction of pruned median selection
// networks: Batcher's odd-even merge sort padded to a power of two, the
// padding (+inf) resolved symbolically, then pruned back from the median so
// only comparators (or their min or max half) that reach it remain.
#pragma once

#include <array>

namespace mcdenoise::network {

/// One comparator: compare slots `a` and `b`; the min goes to `to_min`, the
/// max to `to_max` (either may be the scratch slot when not needed).
struct Op {
    int a, b, to_min, to_max;
};

constexpr int padded_size(int n)
{
    int p = 1;
    while (p < n)
        p *= 2;
    return p;
}

constexpr int log2_of(int p)
{
    int l = 0;
    while ((1 << l) < p)
        ++l;
    return l;
}

/// An upper bound on Batcher's comparator count for `p` inputs.
constexpr int batcher_bound(int p)
{
    const int l = log2_of(p);
    return p * l * (l + 1) / 4 + 1;
}

/// A pruned median network for N (odd) inputs: `ops[0 .. count)`, result in
/// slot `result`, scratch slot N.
template<int N>
struct MedianNet {
    static constexpr int P = padded_size(N);
    std::array<Op, batcher_bound(P)> ops {};
    int count  = 0;
    int result = 0;
};

template<int N>
constexpr MedianNet<N> build_median_net()
{
    constexpr int P        = MedianNet<N>::P;
    constexpr int infinity = -1;
    constexpr int scratch  = N;
    MedianNet<N> net;

    std::array<int, P> slot_of {};
    for (int i = 0; i < P; ++i)
        slot_of[i] = i < N ? i : infinity;
    std::array<Op, batcher_bound(P)> live {};
    int nlive = 0;
    for (int p = 1; p < P; p *= 2)
        for (int k = p; k >= 1; k /= 2)
            for (int j = k % p; j + k < P; j += 2 * k)
                for (int i = 0; i < (k < P - j - k ? k : P - j - k); ++i) {
                    if ((i + j) / (2 * p) != (i + j + k) / (2 * p))
                        continue;
                    const int lo = slot_of[i + j], hi = slot_of[i + j + k];
                    if (lo == infinity) {  // min(+inf, v) = v: just rename
                        slot_of[i + j]     = hi;
                        slot_of[i + j + k] = lo;
                    } else if (hi != infinity) {
                        live[nlive++] = { lo, hi, lo, hi };
                    }
                }
    net.result = slot_of[(N - 1) / 2];

    std::array<bool, N + 1> needed {};
    needed[net.result] = true;
    std::array<Op, batcher_bound(P)> kept {};
    int nkept = 0;
    for (int i = nlive - 1; i >= 0; --i) {
        const Op op = live[i];
        const bool want_min = needed[op.a], want_max = needed[op.b];
        if (!want_min && !want_max)
            continue;
        kept[nkept++] = { op.a, op.b, want_min ? op.a : scratch, want_max ? op.b : scratch };
        needed[op.a] = needed[op.b] = true;
    }
    for (int i = 0; i < nkept; ++i)
        net.ops[i] = kept[nkept - 1 - i];
    net.count = nkept;
    return net;
}

}  // namespace mcdenoise::network
