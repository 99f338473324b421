// normal.cpp: the normal filters: object means weighted by how alike the
// neighbours' normals are.
#include <mcdenoise/normal.h>

#include "walkers/guide_rules.h"
#include "walkers/window_filter.h"

#include <cmath>
#include <tuple>

namespace mcdenoise {

using OIIO::ImageBuf;
using OIIO::ROI;

namespace {

// The dot product of two normals, in float.
float dot(const UnitNormal& a, const UnitNormal& b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

// True when the two normals are the same three values.
bool same_normal(const UnitNormal& a, const UnitNormal& b)
{
    return (a.x == b.x) & (a.y == b.y) & (a.z == b.z);
}

// The normal weight of docs/filters.md: max(0, dot) of unit normals; 1 when both are
// missing, 0 when one is. Identical normals weigh exactly 1, which also
// covers two missing (all-zero) normals; one missing gives a zero dot.
float normal_weight(const UnitNormal& a, const UnitNormal& b)
{
    const float d        = dot(a, b);
    const float positive = d > 0.0f ? d : 0.0f;
    return same_normal(a, b) ? 1.0f : positive;
}

// The smallest window radius with smooth windows: the dot-weighted sums
// cost O(r) per pixel against the exact weights' O(r^2), the same at
// radius 1 (measured in docs/notes/benchmarks.md).
constexpr int smooth_radius_min = 2;

// The cosine of the largest angle between neighbouring normals that keeps
// every normal of a window of radius r within 80 degrees of the center's:
// any pixel of the window is at most 2r steps from the center, and angles
// add up at most along the steps.
float smooth_step_cosine(int r)
{
    constexpr double window_spread_degrees = 80.0, degrees = 3.14159265358979323846 / 180.0;
    return float(std::cos(window_spread_degrees / (2 * r) * degrees));
}

// Normal rule: q viable iff it shares the object id; weight by normals. A
// window is uniform (key 0) when it is one object with one normal, smooth
// (key 1) when it is one object whose neighbouring normals turn by less than
// smooth_step_cosine: every dot in it is then positive, so the weight is the
// plain dot product.
struct SameObjectWeightedByNormal {
    const IdPlane& ids;
    const NormalPlanes& normals;
    UniformMap windows;

    /// The weights depend on the center's id and normal alone: equal ones
    /// share window columns (flat surfaces next to an edge).
    std::tuple<Id, float, float, float> key(int x, int y) const
    {
        const UnitNormal n = normals.at(x, y);
        return { ids.at(x, y), n.x, n.y, n.z };
    }

    void uniform_row(int y, Span xs, uint8_t* out) const { windows.uniform_row(y, xs, 1, out); }
    void smooth_row(int y, Span xs, uint8_t* out) const { windows.uniform_row(y, xs, 2, out); }
    const NormalPlanes& dot_vectors() const { return normals; }
    void row_weights(int px, int py, int qy, Span xs, float* w) const
    {
        const Id* id = ids.from(xs.begin, qy);
        const NormalRow n = normals.from(xs.begin, qy);
        const Id center = ids.at(px, py);
        const UnitNormal center_normal = normals.at(px, py);
        for (int i = 0; i < xs.size(); ++i) {  // branch-free: the compiler vectorises it
            const float weight = normal_weight(center_normal, n[size_t(i)]);
            w[i]               = id[i] == center ? weight : 0.0f;
        }
    }
    void offset_weights(int y, Span xs, int dx, int qy, float* w) const
    {
        const Id* center               = ids.from(xs.begin, y);
        const NormalRow center_normals = normals.from(xs.begin, y);
        const Id* id                   = ids.from(xs.begin + dx, qy);
        const NormalRow n              = normals.from(xs.begin + dx, qy);
        for (int i = 0; i < xs.size(); ++i) {
            const float weight = normal_weight(center_normals[size_t(i)], n[size_t(i)]);
            w[i]               = id[i] == center[i] ? weight : 0.0f;
        }
    }
};

// Where the normal rule's keys change between neighbours, over the ids'
// region (the normals' too), for windows of radius r: bit 0 when the id or
// the normal differs, bit 1 when the id differs or the normals turn by at
// least the angle of smooth_step_cosine (below smooth_radius_min, as bit 0:
// no window is then smooth without being uniform).
KeyChanges normal_key_changes(const IdPlane& ids, const NormalPlanes& normals, int r,
                              int nthreads)
{
    const Id* id      = ids.values.data();
    const NormalRow n = normals.from(ids.region.xbegin, ids.region.ybegin);
    if (r < smooth_radius_min)
        return key_changes(ids.region, nthreads, [id, n](size_t i, size_t j) {
            const bool differ = (id[i] != id[j]) | !same_normal(n[i], n[j]);
            return uint8_t(differ | differ << 1);
        });
    const float smooth = smooth_step_cosine(r);
    return key_changes(ids.region, nthreads, [id, n, smooth](size_t i, size_t j) {
        const bool other = id[i] != id[j];
        const bool turns = !same_normal(n[i], n[j]);
        const bool steep = !(dot(n[i], n[j]) > smooth);
        return uint8_t((other | turns) | (other | steep) << 1);
    });
}

bool normal_filter(const char* op, Reduction reduction, ImageBuf& dst,
                   const ImageBuf& beauty, const ImageBuf& object_id, const ImageBuf& normal,
                   int size, ROI roi, int nthreads)
{
    IdPlane ids;
    NormalPlanes normals;
    if (!check_window_op(op, dst, beauty, size, roi)
        || !load_window_ids(op, dst, beauty, object_id, roi, size, nthreads, ids)
        || !check_guide(op, "normal", dst, normal, 3, roi)
        || !load_normals(op, dst, normal, ids.region, nthreads, normals))
        return false;
    const SameObjectWeightedByNormal rule {
        ids, normals, uniform_map(normal_key_changes(ids, normals, size / 2, nthreads), roi,
                                  size / 2, nthreads)
    };
    return run_window_filter(op, reduction, dst, beauty, { &beauty, &object_id, &normal },
                             size, rule, roi, nthreads);
}

}  // namespace

bool normal_mean(ImageBuf& dst, const ImageBuf& beauty, const ImageBuf& object_id,
                 const ImageBuf& normal, int size, ROI roi, int nthreads)
{
    return normal_filter("normal_mean", Reduction::box_mean, dst, beauty, object_id, normal,
                         size, roi, nthreads);
}

ImageBuf normal_mean(const ImageBuf& beauty, const ImageBuf& object_id,
                     const ImageBuf& normal, int size, ROI roi, int nthreads)
{
    return value_form([&](ImageBuf& dst) {
        return normal_mean(dst, beauty, object_id, normal, size, roi, nthreads);
    });
}

bool normal_gaussian(ImageBuf& dst, const ImageBuf& beauty, const ImageBuf& object_id,
                     const ImageBuf& normal, int size, ROI roi, int nthreads)
{
    return normal_filter("normal_gaussian", Reduction::binomial_mean, dst, beauty, object_id,
                         normal, size, roi, nthreads);
}

ImageBuf normal_gaussian(const ImageBuf& beauty, const ImageBuf& object_id,
                         const ImageBuf& normal, int size, ROI roi, int nthreads)
{
    return value_form([&](ImageBuf& dst) {
        return normal_gaussian(dst, beauty, object_id, normal, size, roi, nthreads);
    });
}

}  // namespace mcdenoise
