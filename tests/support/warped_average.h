// warped_average.h: the simple cross-frame method the cross-frame
// denoise is measured against (docs/temporal.md): per-frame results
// averaged with their motion-carried, depth-checked neighbours.
#pragma once

#include <mcdenoise/temporal.h>

#include <vector>

namespace mcdenoise {

/// Depths agree when their logs differ by at most this (5 %).
constexpr float baseline_depth_tolerance = 0.05f;

/// The baseline: `centre_result` (the centre frame's own `denoise` result)
/// averaged, with equal weights, with `results[i]` (neighbour i's own
/// result) carried into the centre's grid by the motion guides as the
/// cross-frame denoise carries a frame's values (`warp_planes`), at the pixels
/// where the neighbour's depth at the nearest source pixel agrees with the
/// centre's (both infinitely far, or within
/// `baseline_depth_tolerance`; no check without a depth guide). Every
/// result must have the centre beauty's data window and channels.
bool warped_average(OIIO::ImageBuf& dst, const FrameInput& centre,
                    const OIIO::ImageBuf& centre_result, const std::vector<FrameInput>& neighbours,
                    const std::vector<const OIIO::ImageBuf*>& results,
                    const std::vector<int>& offsets, int nthreads = 0);

}  // namespace mcdenoise
