// dof.cpp: the depth-of-field filter: depth levels, their window sides (the
// focus map), and an object mean of each pixel's own side.
#include <mcdenoise/dof.h>

#include "walkers/guide_rules.h"
#include "walkers/window_filter.h"

#include <cmath>
#include <limits>

namespace mcdenoise {

using OIIO::ImageBuf;
using OIIO::ROI;

namespace {

// The window side of every pixel of `roi`, from its depth level.
struct FocusMap {
    Plane<int> sides;
    int largest = 1;
};

bool check_levels(const char* op, ImageBuf& dst, int levels, int focus_level)
{
    if (levels < 1 || focus_level < 0 || focus_level >= levels) {
        dst.errorfmt("{}: need levels >= 1 and 0 <= focus_level < levels, got levels {} "
                     "and focus_level {}",
                     op, levels, focus_level);
        return false;
    }
    const int widest = 1 + 2 * std::max(focus_level, levels - 1 - focus_level);
    if (widest > max_window_size) {
        dst.errorfmt("{}: {} levels focused at {} need a window side of {}, above the "
                     "limit of {}",
                     op, levels, focus_level, widest, max_window_size);
        return false;
    }
    return true;
}

// The smallest and largest finite depths of the plane (the depth over the
// image's data window), so that a pixel's level depends neither on the ROI
// nor on how far the depth guide's data window reaches past the image.
std::pair<double, double> depth_range(const Plane<float>& all)
{
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (float d : all.values)
        if (std::isfinite(d)) {
            lo = std::min(lo, double(d));
            hi = std::max(hi, double(d));
        }
    return { lo, hi };
}

// `image` is the data window whose depths set the range: the beauty's for
// dof, the depth's own for dof_focus_map.
bool focus_map(const char* op, ImageBuf& dst, const ImageBuf& depth, int levels,
               int focus_level, float depth_near, float depth_far, const ROI& roi,
               const ROI& image, int nthreads, FocusMap& map)
{
    Plane<float> all;
    if (!check_levels(op, dst, levels, focus_level)
        || !check_guide(op, "depth", dst, depth, 1, roi)
        || !load_depths(op, dst, depth, OIIO::roi_intersection(image, depth.roi()), nthreads,
                        all))
        return false;
    const bool explicit_range = depth_far > depth_near;
    auto [lo, hi] = explicit_range ? std::make_pair(double(depth_near), double(depth_far))
                                   : depth_range(all);
    map.sides = Plane<int>(roi);
    for (int y = roi.ybegin; y < roi.yend; ++y)
        for (int x = roi.xbegin; x < roi.xend; ++x) {
            const double d = all.at(x, y);
            int level      = levels - 1;
            if (std::isfinite(d) && hi > lo) {
                const double t = (std::clamp(d, lo, hi) - lo) / (hi - lo);
                level = std::min(levels - 1, int(std::floor(levels * t)));
            } else if (std::isfinite(d)) {
                level = 0;
            }
            const int side = 1 + 2 * std::abs(level - focus_level);
            map.sides.at(x, y) = side;
            map.largest = std::max(map.largest, side);
        }
    return true;
}

}  // namespace

bool dof_focus_map(ImageBuf& dst, const ImageBuf& depth, int levels, int focus_level,
                   float depth_near, float depth_far, ROI roi, int nthreads)
{
    const char* op = "dof_focus_map";
    FocusMap map;
    ResultPixels result;
    if (!resolve_roi(op, dst, depth, roi))
        return false;
    roi.chbegin = 0;
    roi.chend   = 1;
    if (!focus_map(op, dst, depth, levels, focus_level, depth_near, depth_far, roi,
                   depth.roi(), nthreads, map)
        || !begin_result(op, dst, depth, { &depth }, roi, result))
        return false;
    for (int y = roi.ybegin; y < roi.yend; ++y)
        for (int x = roi.xbegin; x < roi.xend; ++x)
            *result.pixel(x, y) = float(map.sides.at(x, y));
    return finish_result(op, dst, result);
}

ImageBuf dof_focus_map(const ImageBuf& depth, int levels, int focus_level, float depth_near,
                       float depth_far, ROI roi, int nthreads)
{
    return value_form([&](ImageBuf& dst) {
        return dof_focus_map(dst, depth, levels, focus_level, depth_near, depth_far, roi,
                             nthreads);
    });
}

bool dof(ImageBuf& dst, const ImageBuf& beauty, const ImageBuf& object_id,
         const ImageBuf& depth, int levels, int focus_level, float depth_near,
         float depth_far, ROI roi, int nthreads)
{
    const char* op = "dof";
    FocusMap map;
    IdPlane ids;
    if (!resolve_roi(op, dst, beauty, roi)
        || !focus_map(op, dst, depth, levels, focus_level, depth_near, depth_far, roi,
                      beauty.roi(), nthreads, map)
        || !load_window_ids(op, dst, beauty, object_id, roi, map.largest, nthreads, ids))
        return false;

    // One read of the beauty covers every side's reach; each side present
    // then gets its own kernel and uniform-window map over the same pixels.
    std::vector<int> sides;
    for (int side = 1; side <= map.largest; side += 2)
        if (std::find(map.sides.values.begin(), map.sides.values.end(), side)
            != map.sides.values.end())
            sides.push_back(side);
    ROI region = roi;
    for (int side : sides) {
        const ROI reach = separable_source_region(roi, box_kernel(side), beauty.roi());
        region          = OIIO::roi_union(region, reach);
    }
    region.chbegin = roi.chbegin;
    region.chend   = roi.chend;
    PixelBlock block;
    if (!read_beauty(op, dst, beauty, region, block))
        return false;
    SeparableSource pixels;
    make_separable_source(std::move(block), beauty.roi(), box_kernel(1), nthreads, pixels);
    std::vector<SeparableSource> sources;
    std::vector<SameObject> rules;
    const KeyChanges changes = id_changes(ids, nthreads);
    for (int side : sides) {
        sources.push_back(with_kernel(pixels, box_kernel(side)));
        rules.push_back(same_object_rule(ids, changes, roi, side, nthreads));
    }

    ResultPixels result;
    if (!begin_result(op, dst, beauty, { &beauty, &object_id, &depth }, roi, result))
        return false;
    OIIO::ImageBufAlgo::parallel_image(roi, nthreads, [&](ROI strip) {
        for (size_t i = 0; i < sides.size(); ++i) {
            const int side = sides[i];
            guided_mean_chosen(sources[i], rules[i],
                               [&](int y, Span xs, uint8_t* out) {
                                   const int* row = map.sides.from(xs.begin, y);
                                   for (int j = 0; j < xs.size(); ++j)
                                       out[j] = row[j] == side;
                               },
                               strip, result);
        }
    });
    return finish_result(op, dst, result);
}

ImageBuf dof(const ImageBuf& beauty, const ImageBuf& object_id, const ImageBuf& depth,
             int levels, int focus_level, float depth_near, float depth_far, ROI roi,
             int nthreads)
{
    return value_form([&](ImageBuf& dst) {
        return dof(dst, beauty, object_id, depth, levels, focus_level, depth_near, depth_far,
                   roi, nthreads);
    });
}

}  // namespace mcdenoise
