// object.h: the report's object filters: window filters that only mix a
// pixel with neighbours of the same object, so edges between objects stay.
#pragma once

#include <mcdenoise/export.h>
#include <mcdenoise/simple.h>

MCDENOISE_API_BEGIN

/// Object mean: the mean of the finite values of the neighbours that share
/// the center's object id (one channel, compared as integers after
/// rounding; NaN counts as -1; integer pixel types give the whole numbers
/// they store, not OIIO's [0, 1] scaling). Averaging only within an object
/// keeps hard edges along object boundaries (the report's first
/// improvement over the simple mean). `object_id` must cover the ROI.
ImageBuf object_mean(const ImageBuf& beauty, const ImageBuf& object_id, int size = default_window_size,
                     ROI roi = {}, int nthreads = 0);
/// Write to an existing image `dst` (allocating if it is uninitialized).
bool object_mean(ImageBuf& dst, const ImageBuf& beauty, const ImageBuf& object_id,
                 int size = default_window_size, ROI roi = {}, int nthreads = 0);

/// Object median: the median of the finite values of the neighbours that
/// share the center's object id. Removes outliers (fireflies) without
/// bleeding across object edges; the first half of the report's best chain
/// (`object_median` 7 then `gaussian` 3).
ImageBuf object_median(const ImageBuf& beauty, const ImageBuf& object_id, int size = default_window_size,
                       ROI roi = {}, int nthreads = 0);
/// Write to an existing image `dst` (allocating if it is uninitialized).
bool object_median(ImageBuf& dst, const ImageBuf& beauty, const ImageBuf& object_id,
                   int size = default_window_size, ROI roi = {}, int nthreads = 0);

/// Object gaussian: the binomial-weighted mean of the finite values of the
/// neighbours that share the center's object id, divided by only the
/// weights that contributed. Gives precedence to near neighbours while
/// staying inside the object.
ImageBuf object_gaussian(const ImageBuf& beauty, const ImageBuf& object_id, int size = default_window_size,
                         ROI roi = {}, int nthreads = 0);
/// Write to an existing image `dst` (allocating if it is uninitialized).
bool object_gaussian(ImageBuf& dst, const ImageBuf& beauty, const ImageBuf& object_id,
                     int size = default_window_size, ROI roi = {}, int nthreads = 0);

MCDENOISE_API_END
