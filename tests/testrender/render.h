// render.h: rendering a scene into the beauty and AOV buffers, on any
// number of threads, with results that do not depend on that number.
#pragma once

#include "scene.h"

#include <cstdint>
#include <vector>

namespace testrender {

struct RenderSettings {
    int width = 256;
    int height = 256;
    int spp = 16;
    uint64_t seed = 1;
    int frame = 0;    ///< the scene's frame; samples use frame_seed(seed, frame)
    int threads = 0;  ///< 0: all hardware threads
    bool passes = false;  ///< also produce the light passes (RenderBuffers::passes)
};

/// Interleaved float buffers, row-major, top row first.
struct RenderBuffers {
    int width = 0, height = 0;
    std::vector<float> beauty;    ///< 3 per pixel: mean of all samples
    std::vector<float> albedo;    ///< 3: mean over samples
    std::vector<float> normal;    ///< 3: mean over samples (not renormalised)
    std::vector<float> depth;     ///< 1: center ray
    std::vector<float> id;        ///< 1: center ray
    std::vector<float> reflid;    ///< 1: center ray
    std::vector<float> variance;  ///< 3: sample variance / spp (variance of the mean)
    std::vector<float> half_a;    ///< 3: mean of samples 0, 2, 4, ...
    std::vector<float> half_b;    ///< 3: mean of samples 1, 3, 5, ... (0 if spp == 1)
    std::vector<float> motion;    ///< 4: center ray, MotionVector (x, y, z, w)
    std::vector<float> alpha;     ///< 1: mean coverage; only for a transparent film, else empty
    std::vector<float> passes;    ///< pass_channels: light passes; empty unless asked for
    double seconds = 0;           ///< wall time of the render
};

/// Render `scene` (built at `settings.frame`). Sample s of pixel (x, y)
/// draws its random numbers from SampleRng(frame_seed(seed, frame),
/// y * width + x, s) only.
RenderBuffers render(const Scene& scene, const RenderSettings& settings);

}  // namespace testrender
