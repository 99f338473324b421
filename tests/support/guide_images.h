// guide_images.h: structured auxiliary buffers for the guided-filter tests:
// object ids in blocks with stray pixels, reflect ids on "specular" blocks,
// smooth normals with missing ones, and depth ramps.
#pragma once

#include "support/filter_table.h"

#include <OpenImageIO/imagebuf.h>

#include <cstdint>
#include <vector>

namespace testimg {

/// An image of `width` x `height` pixels of `nchannels` channels stored as
/// `format`, origin (x0, y0), from row-major float `values` (as the nearest
/// whole numbers for the integer formats uint8, uint16, uint32 and int32).
OIIO::ImageBuf from_values(int width, int height, int nchannels, OIIO::TypeDesc format,
                           int x0, int y0, const std::vector<float>& values);

/// One-channel ids: rectangular blocks of a few labels, plus stray single
/// pixels, stored as `format` (float, half, uint32...), origin (x0, y0).
OIIO::ImageBuf block_ids(int width, int height, uint32_t seed,
                         OIIO::TypeDesc format = OIIO::TypeDesc::FLOAT, int x0 = 0,
                         int y0 = 0);

/// One-channel reflect ids: -1 (not specular) on about half the blocks,
/// a few reflected labels elsewhere.
OIIO::ImageBuf block_reflect_ids(int width, int height, uint32_t seed, int x0 = 0,
                                 int y0 = 0);

/// Three-channel normals varying smoothly, not unit length, with some
/// zero-length ("no normal") pixels and flat patches of one normal.
OIIO::ImageBuf wavy_normals(int width, int height, uint32_t seed, int x0 = 0, int y0 = 0);

/// Every guide a filter of the table may read, over `width` x `height` at
/// origin (x0, y0): block ids and reflect ids, wavy normals, a depth ramp
/// with "infinitely far" (1e10) and NaN pixels, random albedo and variance.
testfilters::GuideSet guide_set(int width, int height, uint32_t seed, int x0 = 0, int y0 = 0);

}  // namespace testimg
