// normal.cpp: the normal filters: object means weighted by how alike the
// neighbours' normals are.
#include <mcdenoise/normal.h>

#include "guide_rules.h"
#include "window_filter.h"

namespace mcdenoise {

using OIIO::ImageBuf;
using OIIO::ROI;

namespace {

// SPEC.md's normal weight: max(0, dot) of unit normals; 1 when both are
// missing, 0 when one is. Identical normals weigh exactly 1.
double normal_weight(const UnitNormal& a, const UnitNormal& b)
{
    if (!a.present() || !b.present())
        return a.present() == b.present() ? 1.0 : 0.0;
    if (a.x == b.x && a.y == b.y && a.z == b.z)
        return 1.0;
    const double dot = double(a.x) * b.x + double(a.y) * b.y + double(a.z) * b.z;
    return std::max(0.0, dot);
}

// Normal rule: q viable iff it shares the object id; weight by normals. A
// window is uniform when it is one object with one normal.
struct SameObjectWeightedByNormal {
    const IdPlane& ids;
    const GuidePlane<UnitNormal>& normals;
    UniformMap same_object_and_normal;

    bool uniform(int x, int y) const { return same_object_and_normal.at(x, y); }
    bool viable(int px, int py, int qx, int qy) const
    {
        return ids.at(qx, qy) == ids.at(px, py);
    }
    double weight(int px, int py, int qx, int qy) const
    {
        return normal_weight(normals.at(px, py), normals.at(qx, qy));
    }
};

bool normal_filter(const char* op, Reduction reduction, ImageBuf& dst,
                   const ImageBuf& beauty, const ImageBuf& object_id, const ImageBuf& normal,
                   int size, ROI roi, int nthreads)
{
    IdPlane ids;
    GuidePlane<UnitNormal> normals;
    if (!check_window_op(op, dst, beauty, size, roi)
        || !load_window_ids(op, dst, beauty, object_id, roi, size, nthreads, ids)
        || !check_guide(op, "normal", dst, normal, 3, roi)
        || !load_normals(op, dst, normal, ids.region, nthreads, normals))
        return false;
    const std::vector<int64_t>& id = ids.values;
    const std::vector<UnitNormal>& n = normals.values;
    const SameObjectWeightedByNormal rule {
        ids, normals,
        uniform_map(key_edges(ids.region, nthreads,
                              [&](size_t i, size_t j) {
                                  return id[i] == id[j] && n[i].x == n[j].x && n[i].y == n[j].y
                                         && n[i].z == n[j].z;
                              }),
                    roi, size / 2, nthreads)
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
