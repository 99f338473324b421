// dof.h: the report's depth-of-field filter: an object mean whose window
// grows with the distance of a pixel's depth level from the level in focus.
#pragma once

#include <mcdenoise/defaults.h>
#include <mcdenoise/export.h>
#include <mcdenoise/simple.h>

MCDENOISE_API_BEGIN

/// The window side the `dof` filter uses at each pixel of `roi`, as a one
/// channel float image (the report's "focus map"). The depths' range is
/// [dmin, dmax], the smallest and largest finite depths of `depth`'s data
/// window (values >= 1e9 and non-finite ones are "infinitely far"); when
/// `depth_far > depth_near` that range is [depth_near, depth_far] instead
/// and depths outside it clamp. Each pixel gets level
/// `min(levels-1, floor(levels * (d - dmin) / (dmax - dmin)))` (0 when
/// dmax == dmin; infinitely far pixels take the last level), and window side
/// `1 + 2 * |level - focus_level|`. Requires `levels >= 1`,
/// `0 <= focus_level < levels` and sides of at most 255.
ImageBuf dof_focus_map(const ImageBuf& depth, int levels, int focus_level,
                       float depth_near = dof_image_depth_range, float depth_far = dof_image_depth_range,
                       ROI roi = {}, int nthreads = 0);
/// Write to an existing image `dst` (allocating if it is uninitialized).
bool dof_focus_map(ImageBuf& dst, const ImageBuf& depth, int levels, int focus_level,
                   float depth_near = dof_image_depth_range, float depth_far = dof_image_depth_range,
                   ROI roi = {}, int nthreads = 0);

/// Depth of field: every pixel is replaced by the `object_mean` of the
/// window side `dof_focus_map` gives it, so the level in focus stays sharp
/// and the others are blurred more the further their depth is from it. The
/// report's example: 10 levels, focus 0, gives sides 1 3 5 ... 19 from front
/// to back. Depth must cover the ROI.
ImageBuf dof(const ImageBuf& beauty, const ImageBuf& object_id, const ImageBuf& depth, int levels,
             int focus_level, float depth_near = dof_image_depth_range,
             float depth_far = dof_image_depth_range, ROI roi = {}, int nthreads = 0);
/// Write to an existing image `dst` (allocating if it is uninitialized).
bool dof(ImageBuf& dst, const ImageBuf& beauty, const ImageBuf& object_id,
         const ImageBuf& depth, int levels, int focus_level, float depth_near = dof_image_depth_range,
         float depth_far = dof_image_depth_range, ROI roi = {}, int nthreads = 0);

MCDENOISE_API_END
