// bench_images.h: the images the benchmarks run on.
#pragma once

#include <OpenImageIO/imagebuf.h>

namespace benchimg {

/// A render-like noisy RGB float image: smooth shading with a few object
/// regions, per-pixel Monte Carlo-like noise and rare fireflies.
OIIO::ImageBuf noisy_render(int width = 1920, int height = 1080, int nchannels = 3);

}  // namespace benchimg
