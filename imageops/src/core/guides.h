// guides.h: the auxiliary buffers (object id, reflect id, normal, depth)
// checked against the beauty's ROI and normalised once into contiguous
// planes the hot loops read: ids as 32-bit whole numbers, unit normals,
// depths with "infinitely far" made explicit.
#pragma once

#include "core/plane.h"

#include <OpenImageIO/imagebuf.h>

#include <cstdint>
#include <limits>
#include <vector>

namespace mcdenoise {

/// Check that `guide` (named `name` in messages, e.g. "object_id") is a
/// readable image with `nchannels` channels whose data window covers `roi`.
/// On failure sets `dst`'s error prefixed with `op` and returns false.
bool check_guide(const char* op, const char* name, OIIO::ImageBuf& dst,
                 const OIIO::ImageBuf& guide, int nchannels, const OIIO::ROI& roi);

/// An id as the filters compare it: 32 bits, so comparisons run on 8 SIMD
/// lanes and a 1080p plane takes 8 MB.
using Id = int32_t;

/// Ids, rounded to the nearest whole number; an integer pixel type gives
/// the whole numbers it stores (not OIIO's values scaled to [0, 1]). Ids
/// beyond 32 bits are renumbered densely in their order, which keeps
/// equality and sign.
using IdPlane = Plane<Id>;

/// The id given to pixels outside a guide's data window: equal to no id.
constexpr Id no_guide_id = std::numeric_limits<Id>::min();

/// Object ids over `region`: rounded to nearest, NaN as -1.
bool load_object_ids(const char* op, OIIO::ImageBuf& dst, const OIIO::ImageBuf& ids,
                     const OIIO::ROI& region, int nthreads, IdPlane& plane);

/// Reflect ids over `region`: any negative value (before rounding: -0.4 too)
/// or NaN as -1 ("not specular"), the others rounded to nearest.
bool load_reflect_ids(const char* op, OIIO::ImageBuf& dst, const OIIO::ImageBuf& ids,
                      const OIIO::ROI& region, int nthreads, IdPlane& plane);

/// A normal, unit length, or all zero for "no normal".
struct UnitNormal {
    float x, y, z;  ///< `UnitNormal {}` is all zero
};

/// Normals from one pixel on, read from three component planes.
struct NormalRow {
    const float *x, *y, *z;

    /// The normal `i` pixels on.
    UnitNormal operator[](size_t i) const { return { x[i], y[i], z[i] }; }
};

/// Unit normals over a region, one plane per component (x, y, z), so loops
/// along a row read each as contiguous floats.
struct NormalPlanes {
    Planes<float> components;

    /// The normals from (px, py) on along row py (and the rows below).
    NormalRow from(int px, int py) const
    {
        return { components.from(0, px, py), components.from(1, px, py),
                 components.from(2, px, py) };
    }
    UnitNormal at(int px, int py) const { return from(px, py)[0]; }
};

/// Normals over `region`, normalised; zero-length or non-finite ones (and
/// pixels outside the guide's data window) as "no normal".
bool load_normals(const char* op, OIIO::ImageBuf& dst, const OIIO::ImageBuf& normals,
                  const OIIO::ROI& region, int nthreads, NormalPlanes& planes);

/// Depths at or beyond this are "infinitely far" (Cycles marks background
/// with 1e10).
constexpr float infinitely_far = 1e9f;

/// Depths over `region`; non-finite and >= `infinitely_far` values as +inf.
bool load_depths(const char* op, OIIO::ImageBuf& dst, const OIIO::ImageBuf& depth,
                 const OIIO::ROI& region, int nthreads, Plane<float>& plane);

}  // namespace mcdenoise
