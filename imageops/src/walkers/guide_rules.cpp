// guide_rules.cpp: uniform-window maps from dilated key changes, loading
// ids for a window filter, and the object rule.
#include "walkers/guide_rules.h"

#include "core/window.h"


namespace mcdenoise {

UniformMap uniform_map(const KeyChanges& changes, const OIIO::ROI& roi, int r, int nthreads)
{
    // A dilation of the change flags by the window: an OR down the window's
    // rows (the last row's pairs below leave the window), then along its
    // columns (the last column's pairs to the right leave it), on bytes the
    // compiler vectorises; then both directions folded into one bit per key.
    constexpr uint8_t right_pairs = 0x0f, lower_pairs = 0xf0;
    const OIIO::ROI& reg = changes.region;
    const int x0 = std::max(reg.xbegin, roi.xbegin - r), x1 = std::min(reg.xend, roi.xend + r);
    UniformMap map(roi);
    parallel_rows(roi, nthreads, [&, r](int y) {
        // Columns x0 .. x1 at offset r, zero padding r wide on both sides;
        // bounds copied locally so the byte stores cannot alias them.
        const int nx = x1 - x0, n = roi.width();
        std::vector<uint8_t> padded(size_t(nx + 2 * r), 0);
        uint8_t* any  = padded.data() + r;
        const Span ys = clip_window(y, r, reg.ybegin, reg.yend);
        for (int yy = ys.begin; yy < ys.end; ++yy) {
            const uint8_t keep = yy < y + r ? uint8_t(0xff) : right_pairs;
            const uint8_t* f   = changes.from(x0, yy);
            for (int i = 0; i < nx; ++i)
                any[i] |= f[i] & keep;
        }
        KeyBits* out = map.row(y);
        const uint8_t* from = any + (roi.xbegin - x0) - r;  // window start of roi.xbegin
        std::fill(out, out + n, KeyBits(0));
        for (int d = 0; d < 2 * r; ++d)
            for (int i = 0; i < n; ++i)
                out[i] |= from[i + d];
        const uint8_t* last = from + 2 * r;  // the window's last column
        for (int i = 0; i < n; ++i)
            out[i] = KeyBits(((out[i] | (last[i] & lower_pairs)) >> 4) | (out[i] & right_pairs));
    });
    return map;
}

bool load_window_ids(const char* op, OIIO::ImageBuf& dst, const OIIO::ImageBuf& beauty,
                     const OIIO::ImageBuf& object_id, const OIIO::ROI& roi, int size,
                     int nthreads, IdPlane& ids)
{
    return check_guide(op, "object_id", dst, object_id, 1, roi)
           && load_object_ids(op, dst, object_id, grow_and_clip(roi, size / 2, beauty.roi()),
                              nthreads, ids);
}

KeyChanges id_changes(const IdPlane& ids, int nthreads)
{
    const Id* v = ids.values.data();
    return key_changes(ids.region, nthreads,
                       [v](size_t i, size_t j) { return uint8_t(v[i] != v[j]); });
}

SameObject same_object_rule(const IdPlane& ids, const KeyChanges& changes,
                            const OIIO::ROI& roi, int size, int nthreads)
{
    return { ids, uniform_map(changes, roi, size / 2, nthreads) };
}

}  // namespace mcdenoise
