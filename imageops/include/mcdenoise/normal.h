// normal.h: the report's normal filters: object filters that weigh each
// neighbour by how closely its surface normal matches the center's.
#pragma once

#include <mcdenoise/export.h>
#include <mcdenoise/simple.h>

MCDENOISE_API_BEGIN

/// Normal mean: over the neighbours with the center's object id, the mean
/// weighted by max(0, dot(n_p, n_q)) of the normalised normals (`normal`,
/// three channels, any length). A zero-length normal means "no normal": the
/// weight is 1 when both normals are missing, else 0. The center weighs 1.
/// Pixels facing alike are assumed to be lit alike, which keeps creases and
/// curvature that a plain object mean flattens.
ImageBuf normal_mean(const ImageBuf& beauty, const ImageBuf& object_id,
                     const ImageBuf& normal, int size = default_window_size, ROI roi = {}, int nthreads = 0);
/// Write to an existing image `dst` (allocating if it is uninitialized).
bool normal_mean(ImageBuf& dst, const ImageBuf& beauty, const ImageBuf& object_id,
                 const ImageBuf& normal, int size = default_window_size, ROI roi = {}, int nthreads = 0);

/// Normal gaussian: as `normal_mean`, with each weight also multiplied by
/// the binomial spatial weight.
ImageBuf normal_gaussian(const ImageBuf& beauty, const ImageBuf& object_id,
                         const ImageBuf& normal, int size = default_window_size, ROI roi = {},
                         int nthreads = 0);
/// Write to an existing image `dst` (allocating if it is uninitialized).
bool normal_gaussian(ImageBuf& dst, const ImageBuf& beauty, const ImageBuf& object_id,
                     const ImageBuf& normal, int size = default_window_size, ROI roi = {}, int nthreads = 0);

MCDENOISE_API_END
