// guide_rules.h: the viability rules of the guided filters (SPEC.md), each
// with the map of windows it makes wholly viable (the fast path).
#pragma once

#include "guides.h"
#include "uniform_windows.h"

#include <cstdint>
#include <vector>

namespace mcdenoise {

/// Which ROI pixels' windows are wholly viable.
struct UniformMap {
    OIIO::ROI roi;
    std::vector<uint8_t> flags;

    bool at(int x, int y) const
    {
        return flags[size_t(y - roi.ybegin) * roi.width() + size_t(x - roi.xbegin)];
    }
};

/// The windows of radius `r` around the pixels of `roi` within which every
/// pixel of `region` carries the center's key, keys compared by `same(i, j)`
/// on flat indices of `region`.
template<class Same>
UniformMap uniform_map(const OIIO::ROI& region, const OIIO::ROI& roi, int r, int nthreads,
                       Same&& same)
{
    return { roi, uniform_windows(region, roi, r, nthreads, same) };
}

/// Read a guide's object ids over what a window of side `size` reaches from
/// `roi`, after checking the guide.
bool load_window_ids(const char* op, OIIO::ImageBuf& dst, const OIIO::ImageBuf& beauty,
                     const OIIO::ImageBuf& object_id, const OIIO::ROI& roi, int size,
                     int nthreads, IdPlane& ids);

/// Object rule: q is viable iff id(q) == id(p).
struct SameObject {
    const IdPlane& ids;
    UniformMap uniform_windows;

    bool uniform(int x, int y) const { return uniform_windows.at(x, y); }
    bool viable(int px, int py, int qx, int qy) const
    {
        return ids.at(qx, qy) == ids.at(px, py);
    }
    double weight(int, int, int, int) const { return 1.0; }
};

/// The object rule over `ids` for windows of side `size` around `roi`.
SameObject same_object_rule(const IdPlane& ids, const OIIO::ROI& roi, int size,
                            int nthreads);

}  // namespace mcdenoise
