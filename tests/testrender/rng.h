// rng.h: the counter-based random numbers of the renderer. Every number is a
// pure function of (seed, pixel, sample, dimension), so a render does not
// depend on how pixels are split among threads or in which order they run.
#pragma once

#include <cstdint>

namespace testrender {

/// SplitMix64's finalizer (Steele, Lea, Flood 2014): a bijective 64-bit mix.
inline uint64_t mix64(uint64_t z)
{
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

/// The seed the samples of frame `frame` are drawn with: `seed` itself for
/// frame 0 (so a still render is unchanged by the frame option), otherwise a
/// hash of both, so every frame of a shot has its own, independent noise.
inline uint64_t frame_seed(uint64_t seed, int64_t frame)
{
    if (frame == 0)
        return seed;
    return mix64(mix64(seed ^ 0x632be59bd9b4e019ULL) + uint64_t(frame) * 0x9e3779b97f4a7c15ULL);
}

/// The random stream of one sample of one pixel. `next()` returns the value
/// of dimension 0, 1, 2, ... in turn: hash(key, dimension), where the key
/// hashes (seed, pixel, sample).
class SampleRng {
public:
    SampleRng(uint64_t seed, uint64_t pixel, uint64_t sample)
        : key_(mix64(mix64(mix64(seed + 0x9e3779b97f4a7c15ULL) ^ pixel) + sample))
    {
    }
    /// A uniform double in [0, 1) with 53 random bits.
    double next()
    {
        const uint64_t bits = mix64(key_ + 0x9e3779b97f4a7c15ULL * ++dimension_);
        return double(bits >> 11) * 0x1.0p-53;
    }
    uint32_t dimension() const { return dimension_; }

private:
    uint64_t key_;
    uint32_t dimension_ = 0;
};

}  // namespace testrender
