// guide_rules.cpp: uniform-window maps from dilated key edges, loading
// ids for a window filter, and the object rule.
#include "guide_rules.h"

#include "window.h"


namespace mcdenoise {

UniformMap uniform_map(const KeyEdges& edges, const OIIO::ROI& roi, int r, int nthreads)
{
    // A dilation of the edge flags by the window: an OR down the window's
    // rows, then along its columns, on bytes the compiler vectorises.
    const OIIO::ROI& reg = edges.region;
    const int w = reg.width();
    const int x0 = std::max(reg.xbegin, roi.xbegin - r), x1 = std::min(reg.xend, roi.xend + r);
    UniformMap map { roi, std::vector<uint8_t>(size_t(roi.width()) * roi.height()) };
    parallel_rows(roi, nthreads, [&](int y) {
        // Columns x0 .. x1 at offset r, zero padding r wide on both sides;
        // bounds copied locally so the byte stores cannot alias them.
        const int nx = x1 - x0, n = roi.width();
        std::vector<uint8_t> padded(size_t(nx + 2 * r), 0);
        uint8_t* any  = padded.data() + r;
        const Span ys = clip_window(y, r, reg.ybegin, reg.yend);
        for (int yy = ys.begin; yy < ys.end; ++yy) {
            const uint8_t* e = edges.flags.data() + size_t(yy - reg.ybegin) * w + (x0 - reg.xbegin);
            for (int i = 0; i < nx; ++i)
                any[i] |= e[i];
        }
        uint8_t* out  = map.flags.data() + size_t(y - roi.ybegin) * n;
        const uint8_t* from = any + (roi.xbegin - x0) - r;  // window start of roi.xbegin
        std::fill(out, out + n, uint8_t(0));
        for (int d = 0; d <= 2 * r; ++d)
            for (int i = 0; i < n; ++i)
                out[i] |= from[i + d];
        for (int i = 0; i < n; ++i)
            out[i] = !out[i];
    });
    return map;
}

bool load_window_ids(const char* op, OIIO::ImageBuf& dst, const OIIO::ImageBuf& beauty,
                     const OIIO::ImageBuf& object_id, const OIIO::ROI& roi, int size,
                     int nthreads, IdPlane& ids)
{
    // One pixel past the windows' reach: key edges at the windows' borders
    // then see the same neighbours whatever the ROI, so which windows take
    // the fast path (and so the rounding) never depends on the ROI split.
    return check_guide(op, "object_id", dst, object_id, 1, roi)
           && load_object_ids(op, dst, object_id, grow_and_clip(roi, size / 2 + 1, beauty.roi()),
                              nthreads, ids);
}

KeyEdges id_edges(const IdPlane& ids, int nthreads)
{
    const std::vector<int64_t>& v = ids.values;
    return key_edges(ids.region, nthreads, [&](size_t i, size_t j) { return v[i] == v[j]; });
}

SameObject same_object_rule(const IdPlane& ids, const OIIO::ROI& roi, int size, int nthreads)
{
    return { ids, uniform_map(id_edges(ids, nthreads), roi, size / 2, nthreads) };
}

}  // namespace mcdenoise
