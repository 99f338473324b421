// spec_reference.cpp: the tests' brute-force implementation of docs/filters.md.
#include "spec_reference.h"

#include <algorithm>
#include <cmath>

namespace spec {

Image from_imagebuf(const OIIO::ImageBuf& img)
{
    const OIIO::ROI dw = img.roi();
    Image out;
    out.x0 = dw.xbegin;
    out.y0 = dw.ybegin;
    out.width = dw.width();
    out.height = dw.height();
    out.nchannels = dw.nchannels();
    std::vector<float> f(size_t(out.width) * out.height * out.nchannels);
    img.get_pixels(dw, OIIO::TypeDesc::FLOAT, f.data());
    out.values.assign(f.begin(), f.end());
    return out;
}

namespace {

// The whole numbers of type T stored in `img`'s data window, into `out`.
template<class T>
void stored_whole_numbers(const OIIO::ImageBuf& img, Image& out)
{
    std::vector<T> stored(out.values.size());
    img.get_pixels(img.roi(), img.spec().format, stored.data());
    std::copy(stored.begin(), stored.end(), out.values.begin());
}

}  // namespace

Image ids_from_imagebuf(const OIIO::ImageBuf& img)
{
    Image out = from_imagebuf(img);
    switch (img.spec().format.basetype) {
    case OIIO::TypeDesc::UINT8: stored_whole_numbers<uint8_t>(img, out); break;
    case OIIO::TypeDesc::UINT16: stored_whole_numbers<uint16_t>(img, out); break;
    case OIIO::TypeDesc::UINT32: stored_whole_numbers<uint32_t>(img, out); break;
    case OIIO::TypeDesc::INT32: stored_whole_numbers<int32_t>(img, out); break;
    default: break;
    }
    return out;
}

bool all_viable(int, int, int, int) { return true; }
double unit_weight(int, int, int, int) { return 1.0; }

double binomial(int n, int k)
{
    double c = 1.0;
    for (int i = 1; i <= k; ++i)
        c = c * (n - k + i) / i;
    return std::round(c);
}

namespace {

double median_of(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    if (n % 2 == 1)
        return v[n / 2];
    // The library stores results as float; so does docs/filters.md's "mean of the two
    // middle values" once written to the float output.
    return 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

std::vector<double> filter(const Image& beauty, const OIIO::ROI& roi, int size,
                           Spatial spatial, Reduce reduce, const Viable& viable,
                           const GuideWeight& guide_weight)
{
    const int r = size / 2;
    std::vector<double> out;
    for (int py = roi.ybegin; py < roi.yend; ++py)
        for (int px = roi.xbegin; px < roi.xend; ++px)
            for (int c = roi.chbegin; c < roi.chend; ++c) {
                double sum = 0.0, weights = 0.0;
                std::vector<double> values;
                for (int dy = -r; dy <= r; ++dy)
                    for (int dx = -r; dx <= r; ++dx) {
                        const int qx = px + dx, qy = py + dy;
                        if (!beauty.contains(qx, qy))
                            continue;
                        const bool center = dx == 0 && dy == 0;
                        if (!center && !viable(px, py, qx, qy))
                            continue;
                        const double v = beauty.at(qx, qy, c);
                        if (!std::isfinite(v))
                            continue;
                        const double s = spatial == Spatial::box
                                             ? 1.0
                                             : binomial(size - 1, dx + r)
                                                   * binomial(size - 1, dy + r);
                        const double w = s * (center ? 1.0 : guide_weight(px, py, qx, qy));
                        sum += w * v;
                        weights += w;
                        values.push_back(v);
                    }
                if (values.empty())
                    out.push_back(0.0);
                else if (reduce == Reduce::median)
                    out.push_back(median_of(values));
                else
                    out.push_back(weights > 0.0 ? sum / weights : 0.0);
            }
    return out;
}

}  // namespace spec
