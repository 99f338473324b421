// plane.h: the one layout of per-pixel data over a region of an image:
// `Plane<T>`, one value per pixel in rows of the region's width (ids,
// depths, change flags, window sides), and `Planes<T>`, several such
// planes over one region (colour channels, feature dimensions, summed
// values) with an optional mask of which values are finite; and the offsets
// of interleaved pixels (pixel_block.h, operation.h). Every offset into them
// is computed here, so hot loops take contiguous rows from
// `from` or `row` and index them by column.
#pragma once

#include "core/large_buffer.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace mcdenoise {

/// The row-major index of pixel (x, y), which must lie in `region`.
inline size_t pixel_offset(const OIIO::ROI& region, int x, int y)
{
    return size_t(y - region.ybegin) * size_t(region.width()) + size_t(x - region.xbegin);
}

/// The index of the first value of pixel (x, y), which must lie in
/// `region`, in interleaved rows: `pixel_stride` values a pixel, rows
/// `row_stride` values apart (the layout of an image's own pixels).
inline std::ptrdiff_t interleaved_offset(const OIIO::ROI& region, int x, int y, std::ptrdiff_t row_stride,
                                         std::ptrdiff_t pixel_stride)
{
    return (y - region.ybegin) * row_stride + std::ptrdiff_t(x - region.xbegin) * pixel_stride;
}

/// The pixel count of `region`: the length of one of its planes.
inline size_t plane_size(const OIIO::ROI& region)
{
    return size_t(region.width()) * size_t(region.height());
}

/// One value of type T per pixel of `region`, row-major, rows
/// `region.width()` values long.
template<class T>
struct Plane {
    OIIO::ROI region;
    LargeVector<T> values;

    Plane() = default;
    /// A plane over `region` whose values are left unset: the caller writes
    /// every one before reading it.
    explicit Plane(const OIIO::ROI& region_)
        : region(region_), values(plane_size(region_))
    {
    }
    /// A plane over `region` with every value `fill`.
    Plane(const OIIO::ROI& region_, T fill)
        : region(region_), values(plane_size(region_), fill)
    {
    }

    /// The index of (x, y) in `values`.
    size_t offset(int x, int y) const { return pixel_offset(region, x, y); }
    /// The values from (x, y) on along row y (and the rows below).
    const T* from(int x, int y) const { return values.data() + offset(x, y); }
    T* from(int x, int y) { return values.data() + offset(x, y); }
    /// Row y, from `region.xbegin`.
    const T* row(int y) const { return from(region.xbegin, y); }
    T* row(int y) { return from(region.xbegin, y); }
    const T& at(int x, int y) const { return values[offset(x, y)]; }
    T& at(int x, int y) { return values[offset(x, y)]; }
};

/// The values of `plane` over `part` (which it must contain) as a plane of
/// their own.
template<class T>
Plane<T> cropped(const Plane<T>& plane, const OIIO::ROI& part)
{
    Plane<T> out(part);
    for (int y = part.ybegin; y < part.yend; ++y)
        std::copy_n(plane.from(part.xbegin, y), part.width(), out.row(y));
    return out;
}

/// Channel planes over one region, each laid out as a `Plane<T>`, and, when
/// some source value was not finite, a mask plane per channel holding 1
/// where the value was finite and 0 where not.
template<class T>
struct Planes {
    OIIO::ROI region;
    std::vector<LargeVector<T>> values;  ///< one plane per channel
    std::vector<LargeVector<T>> finite;  ///< empty when every value is finite

    Planes() = default;
    /// `nchannels` planes over `region` whose values are left unset.
    Planes(const OIIO::ROI& region_, int nchannels)
        : region(region_)
    {
        for (int c = 0; c < nchannels; ++c)
            values.emplace_back(plane_size(region_));
    }
    /// `nchannels` planes over `region` with every value `fill`.
    Planes(const OIIO::ROI& region_, int nchannels, T fill)
        : region(region_), values(size_t(nchannels), LargeVector<T>(plane_size(region_), fill))
    {
    }

    int nchannels() const { return int(values.size()); }
    bool masked() const { return !finite.empty(); }
    /// The index of (x, y) in each plane.
    size_t offset(int x, int y) const { return pixel_offset(region, x, y); }
    /// Channel c's values from (x, y) on along row y.
    const T* from(int c, int x, int y) const { return values[size_t(c)].data() + offset(x, y); }
    T* from(int c, int x, int y) { return values[size_t(c)].data() + offset(x, y); }
    /// Channel c's row y, from `region.xbegin`.
    const T* row(int c, int y) const { return from(c, region.xbegin, y); }
    T* row(int c, int y) { return from(c, region.xbegin, y); }
    /// Channel c's finite mask from (x, y) on along row y (needs `masked()`).
    const T* finite_from(int c, int x, int y) const
    {
        return finite[size_t(c)].data() + offset(x, y);
    }
    /// Channel c's finite mask row y, from `region.xbegin` (needs `masked()`).
    T* finite_row(int c, int y) { return finite[size_t(c)].data() + offset(region.xbegin, y); }
    /// Give planes that have no finite mask one saying every value is
    /// finite (1 everywhere), as planes summed along with masked ones need.
    void mask_all_finite()
    {
        if (!masked())
            finite.assign(values.size(), LargeVector<T>(plane_size(region), T(1)));
    }
};

}  // namespace mcdenoise
