// guide_rules.cpp: uniform-window maps from box sums of key edges, loading
// ids for a window filter, and the object rule.
#include "guide_rules.h"

#include "separable_mean.h"
#include "window.h"

#include <OpenImageIO/imagebufalgo_util.h>

namespace mcdenoise {

UniformMap uniform_map(PixelBlock edges, const OIIO::ROI& roi, int r, int nthreads)
{
    // Box sums of 0/1 values are exact small integers from any restart
    // point, so they restart from the edge block's own corner.
    const OIIO::ROI region = edges.region;
    SeparableSource counts;
    make_separable_source(std::move(edges), region, box_kernel(2 * r + 1), nthreads, counts);
    OIIO::ROI one = roi;
    one.chbegin   = 0;
    one.chend     = 1;
    ResultPixels share;
    share.use_buffer(one);
    OIIO::ImageBufAlgo::parallel_image(one, nthreads, [&](OIIO::ROI strip) {
        separable_mean_strip(counts, strip, share);
    });
    UniformMap map { one, std::vector<uint8_t>(size_t(one.width()) * one.height()) };
    for (int y = one.ybegin; y < one.yend; ++y) {
        const float* s = share.pixel(one.xbegin, y);
        uint8_t* f     = map.flags.data() + size_t(y - one.ybegin) * one.width();
        for (int x = 0; x < one.width(); ++x)
            f[x] = s[x] == 0.0f;
    }
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

PixelBlock id_edges(const IdPlane& ids, int nthreads)
{
    const std::vector<int64_t>& v = ids.values;
    return key_edges(ids.region, nthreads, [&](size_t i, size_t j) { return v[i] == v[j]; });
}

SameObject same_object_rule(const IdPlane& ids, const OIIO::ROI& roi, int size, int nthreads)
{
    return { ids, uniform_map(id_edges(ids, nthreads), roi, size / 2, nthreads) };
}

}  // namespace mcdenoise
