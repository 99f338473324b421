// brdf.h: the report's BRDF filters: object filters that, on a specular
// pixel, also require the neighbour's mirror reflection to show the same
// object, so reflections stay sharp.
#pragma once

#include <mcdenoise/export.h>
#include <mcdenoise/simple.h>

MCDENOISE_API_BEGIN

/// BRDF mean. If the center is specular (`reflect_id` >= 0: the id of the
/// object its mirror-reflection ray hit), a neighbour is viable when it has
/// the center's object id and the same reflect id; otherwise when it has the
/// center's object id. Mixing only pixels that reflect the same object keeps
/// the detail of reflections, which the object filters blur. Ids compare
/// rounded to nearest; any negative reflect id (-0.4 too) or NaN means "not
/// specular".
ImageBuf brdf_mean(const ImageBuf& beauty, const ImageBuf& object_id, const ImageBuf& reflect_id,
                   int size = default_window_size, ROI roi = {}, int nthreads = 0);
/// Write to an existing image `dst` (allocating if it is uninitialized).
bool brdf_mean(ImageBuf& dst, const ImageBuf& beauty, const ImageBuf& object_id,
               const ImageBuf& reflect_id, int size = default_window_size, ROI roi = {}, int nthreads = 0);

/// BRDF gaussian: the binomial-weighted mean over the neighbours the BRDF
/// rule (see `brdf_mean`) makes viable, divided by the weights that
/// contributed.
ImageBuf brdf_gaussian(const ImageBuf& beauty, const ImageBuf& object_id,
                       const ImageBuf& reflect_id, int size = default_window_size, ROI roi = {},
                       int nthreads = 0);
/// Write to an existing image `dst` (allocating if it is uninitialized).
bool brdf_gaussian(ImageBuf& dst, const ImageBuf& beauty, const ImageBuf& object_id,
                   const ImageBuf& reflect_id, int size = default_window_size, ROI roi = {},
                   int nthreads = 0);

/// BRDF median (beyond the report): the median over the neighbours the BRDF
/// rule (see `brdf_mean`) makes viable, for fireflies on mirrors.
ImageBuf brdf_median(const ImageBuf& beauty, const ImageBuf& object_id,
                     const ImageBuf& reflect_id, int size = default_window_size, ROI roi = {},
                     int nthreads = 0);
/// Write to an existing image `dst` (allocating if it is uninitialized).
bool brdf_median(ImageBuf& dst, const ImageBuf& beauty, const ImageBuf& object_id,
                 const ImageBuf& reflect_id, int size = default_window_size, ROI roi = {}, int nthreads = 0);

MCDENOISE_API_END
