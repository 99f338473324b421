// object.cpp: the object filters: mean, median and gaussian over the
// neighbours that share the center's object id.
#include <mcdenoise/object.h>

#include "walkers/guide_rules.h"
#include "walkers/window_filter.h"

namespace mcdenoise {

using OIIO::ImageBuf;
using OIIO::ROI;

namespace {

bool object_filter(const char* op, Reduction reduction, ImageBuf& dst,
                   const ImageBuf& beauty, const ImageBuf& object_id, int size, ROI roi,
                   int nthreads)
{
    IdPlane ids;
    if (!check_window_op(op, dst, beauty, size, roi)
        || !load_window_ids(op, dst, beauty, object_id, roi, size, nthreads, ids))
        return false;
    const SameObject rule = same_object_rule(ids, id_changes(ids, nthreads), roi, size, nthreads);
    return run_window_filter(op, reduction, dst, beauty, { &beauty, &object_id }, size, rule, roi,
                             nthreads);
}

}  // namespace

bool object_mean(ImageBuf& dst, const ImageBuf& beauty, const ImageBuf& object_id, int size,
                 ROI roi, int nthreads)
{
    return object_filter("object_mean", Reduction::box_mean, dst, beauty, object_id, size,
                         roi, nthreads);
}

ImageBuf object_mean(const ImageBuf& beauty, const ImageBuf& object_id, int size, ROI roi,
                     int nthreads)
{
    return value_form([&](ImageBuf& dst) {
        return object_mean(dst, beauty, object_id, size, roi, nthreads);
    });
}

bool object_median(ImageBuf& dst, const ImageBuf& beauty, const ImageBuf& object_id,
                   int size, ROI roi, int nthreads)
{
    return object_filter("object_median", Reduction::median, dst, beauty, object_id, size,
                         roi, nthreads);
}

ImageBuf object_median(const ImageBuf& beauty, const ImageBuf& object_id, int size, ROI roi,
                       int nthreads)
{
    return value_form([&](ImageBuf& dst) {
        return object_median(dst, beauty, object_id, size, roi, nthreads);
    });
}

bool object_gaussian(ImageBuf& dst, const ImageBuf& beauty, const ImageBuf& object_id,
                     int size, ROI roi, int nthreads)
{
    return object_filter("object_gaussian", Reduction::binomial_mean, dst, beauty, object_id,
                         size, roi, nthreads);
}

ImageBuf object_gaussian(const ImageBuf& beauty, const ImageBuf& object_id, int size,
                         ROI roi, int nthreads)
{
    return value_form([&](ImageBuf& dst) {
        return object_gaussian(dst, beauty, object_id, size, roi, nthreads);
    });
}

}  // namespace mcdenoise
