// warped_average.cpp: the warped average of per-frame results.
#include "support/warped_average.h"

#include "core/guides.h"
#include "core/pixel_block.h"
#include "shots/frame_warp.h"

#include <cmath>

namespace mcdenoise {

using OIIO::ImageBuf;
using OIIO::ROI;

namespace {

constexpr const char* op_name = "warped_average";

bool depths_agree(float a, float b)
{
    if (std::isinf(a) || std::isinf(b))
        return std::isinf(a) && std::isinf(b);
    return a > 0.0f && b > 0.0f && std::fabs(std::log(a / b)) <= baseline_depth_tolerance;
}

bool read(ImageBuf& dst, const ImageBuf& img, const ROI& dw, PixelBlock& block)
{
    if (!img.initialized() || img.nchannels() != dw.chend || !load_block(img, dw, block)) {
        dst.errorfmt("{}: a result does not match the centre frame: {}", op_name,
                     img.geterror());
        return false;
    }
    return true;
}

}  // namespace

bool warped_average(ImageBuf& dst, const FrameInput& centre, const ImageBuf& centre_result,
                    const std::vector<FrameInput>& neighbours,
                    const std::vector<const ImageBuf*>& results, const std::vector<int>& offsets,
                    int nthreads)
{
    ROI dw     = centre.beauty->roi();
    dw.chbegin = 0;
    dw.chend   = centre.beauty->nchannels();
    std::vector<std::unique_ptr<GuideChannels>> motions;
    PixelBlock own;
    Plane<float> depth;
    if (!load_motions(op_name, dst, centre, neighbours, nthreads, motions)
        || !read(dst, centre_result, dw, own)
        || (centre.guides.depth
            && !load_depths(op_name, dst, *centre.guides.depth, dw, nthreads, depth)))
        return false;
    std::vector<const GuideChannels*> motion_of;
    for (const auto& m : motions)
        motion_of.push_back(m.get());
    const int nc = dw.chend;
    std::vector<float> sum(own.data, own.data + dw.npixels() * size_t(nc));
    std::vector<float> count(dw.npixels(), 1.0f);
    for (size_t i = 0; i < neighbours.size(); ++i) {
        PixelBlock other;
        Plane<float> other_depth;
        if (!read(dst, *results[i], dw, other)
            || (centre.guides.depth
                && !load_depths(op_name, dst, *neighbours[i].guides.depth, dw, nthreads,
                                other_depth)))
            return false;
        const WarpMap map = motion_warp_map(motion_steps(motion_of, offsets, offsets[i]),
                                            offsets[i], dw, dw, nthreads);
        const Planes<float> warped = warp_planes(channel_planes(other, nthreads), map, dw, nthreads);
        for (int y = dw.ybegin; y < dw.yend; ++y)
            for (int x = dw.xbegin; x < dw.xend; ++x) {
                const size_t p = map.xs.offset(x, y);
                if (!map.has_source(p)
                    || (centre.guides.depth
                        && !depths_agree(depth.values[p],
                                         other_depth.at(map.xs.values[p], map.ys.values[p]))))
                    continue;
                for (int c = 0; c < nc; ++c)
                    sum[p * size_t(nc) + size_t(c)] += warped.values[size_t(c)][p];
                count[p] += 1.0f;
            }
    }
    for (size_t p = 0; p < count.size(); ++p)
        for (int c = 0; c < nc; ++c)
            sum[p * size_t(nc) + size_t(c)] /= count[p];
    OIIO::ImageSpec spec(dw, OIIO::TypeDesc::FLOAT);
    dst.reset(spec);
    return dst.set_pixels(dw, OIIO::TypeDesc::FLOAT, sum.data());
}

}  // namespace mcdenoise
