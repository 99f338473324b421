// guide_rules.cpp: loading ids for a window filter, and the object rule.
#include "guide_rules.h"

#include "window.h"

namespace mcdenoise {

bool load_window_ids(const char* op, OIIO::ImageBuf& dst, const OIIO::ImageBuf& beauty,
                     const OIIO::ImageBuf& object_id, const OIIO::ROI& roi, int size,
                     int nthreads, IdPlane& ids)
{
    return check_guide(op, "object_id", dst, object_id, 1, roi)
           && load_object_ids(op, dst, object_id, grow_and_clip(roi, size / 2, beauty.roi()),
                              nthreads, ids);
}

SameObject same_object_rule(const IdPlane& ids, const OIIO::ROI& roi, int size, int nthreads)
{
    const std::vector<int64_t>& v = ids.values;
    return { ids, uniform_map(ids.region, roi, size / 2, nthreads,
                              [&](size_t i, size_t j) { return v[i] == v[j]; }) };
}

}  // namespace mcdenoise
