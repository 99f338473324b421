// window.cpp: window size checks and window geometry.
#include "core/window.h"

#include <mcdenoise/simple.h>

#include <OpenImageIO/strutil.h>

namespace mcdenoise {

std::string check_window_size(int size)
{
    if (size < 1 || size > max_window_size)
        return OIIO::Strutil::fmt::format("size must be between 1 and {}, got {}",
                                          max_window_size, size);
    if (size % 2 == 0)
        return OIIO::Strutil::fmt::format("size must be odd, got {}", size);
    return {};
}

OIIO::ROI grow_and_clip(const OIIO::ROI& roi, int radius, const OIIO::ROI& bounds)
{
    OIIO::ROI r = roi;
    r.xbegin    = std::max(bounds.xbegin, roi.xbegin - radius);
    r.xend      = std::min(bounds.xend, roi.xend + radius);
    r.ybegin    = std::max(bounds.ybegin, roi.ybegin - radius);
    r.yend      = std::min(bounds.yend, roi.yend + radius);
    return r;
}

int restart_interval(int radius)
{
    constexpr int min_interval = 64;
    return std::max(min_interval, 4 * (2 * radius + 1));
}

int restart_at_or_before(int x, int origin, int interval)
{
    const int offset = x - origin;
    const int floor_div = offset >= 0 ? offset / interval
                                      : -((-offset + interval - 1) / interval);
    return origin + floor_div * interval;
}

}  // namespace mcdenoise
