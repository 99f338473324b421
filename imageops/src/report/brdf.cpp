// brdf.cpp: the BRDF filters: object filters that, on specular pixels, also
// require the same reflected object.
#include <mcdenoise/brdf.h>

#include "walkers/guide_rules.h"
#include "walkers/window_filter.h"

namespace mcdenoise {

using OIIO::ImageBuf;
using OIIO::ROI;

namespace {

// BRDF rule: on a specular center (reflect id >= 0) q must share both the
// object id and the reflect id; elsewhere the object id. Key 0 is the
// object id, key 1 the reflect id.
struct SameObjectAndReflection {
    const IdPlane& ids;
    const IdPlane& reflect;
    UniformMap windows;

    bool specular(int x, int y) const { return reflect.at(x, y) >= 0; }

    /// The weights depend on the center's ids alone.
    int64_t key(int x, int y) const
    {
        return int64_t(ids.at(x, y)) * (int64_t(1) << 32) + int64_t(reflect.at(x, y));
    }
    void uniform_row(int y, Span xs, uint8_t* out) const
    {
        const KeyBits* changed = windows.from(xs.begin, y);
        const Id* rid     = reflect.from(xs.begin, y);
        for (int i = 0; i < xs.size(); ++i)
            out[i] = !(changed[i] & (rid[i] >= 0 ? KeyBits(3) : KeyBits(1)));
    }
    void row_weights(int px, int py, int qy, Span xs, float* w) const
    {
        const Id* id = ids.from(xs.begin, qy);
        const Id center = ids.at(px, py);
        if (!specular(px, py))
            return matching_keys(id, center, xs, w);
        const Id* rid = reflect.from(xs.begin, qy);
        const Id center_rid = reflect.at(px, py);
        for (int i = 0; i < xs.size(); ++i)
            w[i] = id[i] == center && rid[i] == center_rid ? 1.0f : 0.0f;
    }
    void offset_weights(int y, Span xs, int dx, int qy, float* w) const
    {
        const Id* center     = ids.from(xs.begin, y);
        const Id* center_rid = reflect.from(xs.begin, y);
        const Id* id         = ids.from(xs.begin + dx, qy);
        const Id* rid        = reflect.from(xs.begin + dx, qy);
        for (int i = 0; i < xs.size(); ++i)
            w[i] = id[i] == center[i] && (center_rid[i] < 0 || rid[i] == center_rid[i]) ? 1.0f
                                                                                          : 0.0f;
    }
};

bool brdf_filter(const char* op, Reduction reduction, ImageBuf& dst, const ImageBuf& beauty,
                 const ImageBuf& object_id, const ImageBuf& reflect_id, int size, ROI roi,
                 int nthreads)
{
    IdPlane ids, reflect;
    if (!check_window_op(op, dst, beauty, size, roi)
        || !load_window_ids(op, dst, beauty, object_id, roi, size, nthreads, ids)
        || !check_guide(op, "reflect_id", dst, reflect_id, 1, roi)
        || !load_reflect_ids(op, dst, reflect_id, ids.region, nthreads, reflect))
        return false;
    const Id *id = ids.values.data(), *rid = reflect.values.data();
    const SameObjectAndReflection rule {
        ids, reflect,
        uniform_map(key_changes(ids.region, nthreads,
                                [id, rid](size_t i, size_t j) {
                                    return uint8_t((id[i] != id[j]) | (rid[i] != rid[j]) << 1);
                                }),
                    roi, size / 2, nthreads)
    };
    return run_window_filter(op, reduction, dst, beauty,
                             { &beauty, &object_id, &reflect_id }, size, rule, roi, nthreads);
}

}  // namespace

bool brdf_mean(ImageBuf& dst, const ImageBuf& beauty, const ImageBuf& object_id,
               const ImageBuf& reflect_id, int size, ROI roi, int nthreads)
{
    return brdf_filter("brdf_mean", Reduction::box_mean, dst, beauty, object_id, reflect_id,
                       size, roi, nthreads);
}

ImageBuf brdf_mean(const ImageBuf& beauty, const ImageBuf& object_id,
                   const ImageBuf& reflect_id, int size, ROI roi, int nthreads)
{
    return value_form([&](ImageBuf& dst) {
        return brdf_mean(dst, beauty, object_id, reflect_id, size, roi, nthreads);
    });
}

bool brdf_gaussian(ImageBuf& dst, const ImageBuf& beauty, const ImageBuf& object_id,
                   const ImageBuf& reflect_id, int size, ROI roi, int nthreads)
{
    return brdf_filter("brdf_gaussian", Reduction::binomial_mean, dst, beauty, object_id,
                       reflect_id, size, roi, nthreads);
}

ImageBuf brdf_gaussian(const ImageBuf& beauty, const ImageBuf& object_id,
                       const ImageBuf& reflect_id, int size, ROI roi, int nthreads)
{
    return value_form([&](ImageBuf& dst) {
        return brdf_gaussian(dst, beauty, object_id, reflect_id, size, roi, nthreads);
    });
}

bool brdf_median(ImageBuf& dst, const ImageBuf& beauty, const ImageBuf& object_id,
                 const ImageBuf& reflect_id, int size, ROI roi, int nthreads)
{
    return brdf_filter("brdf_median", Reduction::median, dst, beauty, object_id, reflect_id,
                       size, roi, nthreads);
}

ImageBuf brdf_median(const ImageBuf& beauty, const ImageBuf& object_id,
                     const ImageBuf& reflect_id, int size, ROI roi, int nthreads)
{
    return value_form([&](ImageBuf& dst) {
        return brdf_median(dst, beauty, object_id, reflect_id, size, roi, nthreads);
    });
}

}  // namespace mcdenoise
