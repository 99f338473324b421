// separable_sum.cpp: sliding box sums and direct separable convolution, in
// double precision, with fixed restart points for split-independent results.
#include "separable_sum.h"

#include "window.h"

#include <algorithm>

namespace mcdenoise {

using OIIO::ROI;

Kernel1D box_kernel(int size)
{
    Kernel1D k;
    k.radius  = size / 2;
    k.box     = true;
    k.weights.assign(size_t(size), 1.0);
    return k;
}

Kernel1D binomial_kernel(int size)
{
    Kernel1D k;
    k.radius = size / 2;
    k.weights.assign(size_t(size), 0.0);
    k.weights[0] = 1.0;
    for (int n = 1; n < size; ++n) {  // next row of Pascal's triangle, halved
        for (int i = n; i >= 1; --i)
            k.weights[i] = 0.5 * (k.weights[i] + k.weights[i - 1]);
        k.weights[0] *= 0.5;
    }
    return k;
}

ROI separable_source_region(const ROI& roi, const Kernel1D& kernel, const ROI& bounds)
{
    ROI grown = roi;
    if (kernel.box) {
        const int interval = restart_interval(kernel.radius);
        grown.xbegin = restart_at_or_before(roi.xbegin, bounds.xbegin, interval);
        grown.ybegin = restart_at_or_before(roi.ybegin, bounds.ybegin, interval);
    }
    return grow_and_clip(grown, kernel.radius, bounds);
}

double window_weight(const Kernel1D& kernel, int x, int y, const ROI& region)
{
    const int r        = kernel.radius;
    const Span xs      = clip_window(x, r, region.xbegin, region.xend);
    const Span ys      = clip_window(y, r, region.ybegin, region.yend);
    if (kernel.box)
        return double(xs.size()) * double(ys.size());
    double row = 0.0;
    for (int i = xs.begin; i < xs.end; ++i)
        row += kernel.weights[size_t(i - x + r)] * 1.0;
    double sum = 0.0;
    for (int j = ys.begin; j < ys.end; ++j)
        sum += kernel.weights[size_t(j - y + r)] * row;
    return sum;
}

namespace {

// Rows of per-pixel sums for one strip, kept in a ring so each source row's
// horizontal pass runs once.
class RowRing {
public:
    RowRing(int rows, size_t row_len)
        : m_rows(rows), m_len(row_len), m_data(size_t(rows) * row_len)
    {
    }
    double* operator[](int y)
    {
        const int slot = ((y % m_rows) + m_rows) % m_rows;
        return m_data.data() + size_t(slot) * m_len;
    }

private:
    int m_rows;
    size_t m_len;
    std::vector<double> m_data;
};

// Box sums along row y for x in strip, restarting at fixed points.
void box_row(const PixelBlock& src, int r, int origin_x, int y, const ROI& strip,
             double* out)
{
    const int nc       = src.nchannels;
    const int interval = restart_interval(r);
    const int lo = src.region.xbegin, hi = src.region.xend;
    const int xb = restart_at_or_before(strip.xbegin, origin_x, interval);
    std::vector<double> s(size_t(nc), 0.0);
    for (int x = xb; x < strip.xend; ++x) {
        if (x == xb || (x - origin_x) % interval == 0) {
            const Span span = clip_window(x, r, lo, hi);
            std::fill(s.begin(), s.end(), 0.0);
            for (int xx = span.begin; xx < span.end; ++xx) {
                const float* v = src.pixel(xx, y);
                for (int c = 0; c < nc; ++c)
                    s[c] += v[c];
            }
        } else {
            if (x + r < hi) {
                const float* v = src.pixel(x + r, y);
                for (int c = 0; c < nc; ++c)
                    s[c] += v[c];
            }
            if (x - r - 1 >= lo) {
                const float* v = src.pixel(x - r - 1, y);
                for (int c = 0; c < nc; ++c)
                    s[c] -= v[c];
            }
        }
        if (x >= strip.xbegin)
            std::copy(s.begin(), s.end(), out + size_t(x - strip.xbegin) * nc);
    }
}

void box_sums(const PixelBlock& src, int r, SumOrigin origin, const ROI& strip,
              double* sums)
{
    const size_t len   = size_t(strip.width()) * src.nchannels;
    const int interval = restart_interval(r);
    const int lo = src.region.ybegin, hi = src.region.yend;
    const int yb = restart_at_or_before(strip.ybegin, origin.y, interval);
    RowRing rows(2 * r + 2, len);
    int next = std::max(lo, yb - r);
    auto ensure = [&](int y) {
        for (; next <= std::min(y, hi - 1); ++next)
            box_row(src, r, origin.x, next, strip, rows[next]);
    };
    std::vector<double> col(len, 0.0);
    for (int y = yb; y < strip.yend; ++y) {
        if (y == yb || (y - origin.y) % interval == 0) {
            const Span span = clip_window(y, r, lo, hi);
            ensure(span.end - 1);
            std::fill(col.begin(), col.end(), 0.0);
            for (int yy = span.begin; yy < span.end; ++yy) {
                const double* h = rows[yy];
                for (size_t i = 0; i < len; ++i)
                    col[i] += h[i];
            }
        } else {
            if (y + r < hi) {
                ensure(y + r);
                const double* h = rows[y + r];
                for (size_t i = 0; i < len; ++i)
                    col[i] += h[i];
            }
            if (y - r - 1 >= lo) {
                const double* h = rows[y - r - 1];
                for (size_t i = 0; i < len; ++i)
                    col[i] -= h[i];
            }
        }
        if (y >= strip.ybegin)
            std::copy(col.begin(), col.end(), sums + size_t(y - strip.ybegin) * len);
    }
}

// Weighted sums along row y for x in strip: interior pixels as one flat loop
// over (x, channel), pixels near the data window's edge tap by tap.
void direct_row(const PixelBlock& src, const Kernel1D& k, int y, const ROI& strip,
                double* out)
{
    const int nc = src.nchannels, r = k.radius;
    const int lo = src.region.xbegin, hi = src.region.xend;
    const int in_begin = std::clamp(lo + r, strip.xbegin, strip.xend);
    const int in_end   = std::clamp(hi - r, in_begin, strip.xend);
    auto edge_pixel = [&](int x) {
        const Span span = clip_window(x, r, lo, hi);
        double* o = out + size_t(x - strip.xbegin) * nc;
        std::fill(o, o + nc, 0.0);
        for (int xx = span.begin; xx < span.end; ++xx) {
            const double w = k.weights[size_t(xx - x + r)];
            const float* v = src.pixel(xx, y);
            for (int c = 0; c < nc; ++c)
                o[c] += w * v[c];
        }
    };
    for (int x = strip.xbegin; x < in_begin; ++x)
        edge_pixel(x);
    if (in_end > in_begin) {
        double* o       = out + size_t(in_begin - strip.xbegin) * nc;
        const size_t n  = size_t(in_end - in_begin) * nc;
        std::fill(o, o + n, 0.0);
        for (int j = 0; j <= 2 * r; ++j) {
            const double w = k.weights[size_t(j)];
            const float* v = src.pixel(in_begin + j - r, y);
            for (size_t i = 0; i < n; ++i)
                o[i] += w * v[i];
        }
    }
    for (int x = in_end; x < strip.xend; ++x)
        edge_pixel(x);
}

void direct_sums(const PixelBlock& src, const Kernel1D& k, const ROI& strip,
                 double* sums)
{
    const size_t len = size_t(strip.width()) * src.nchannels;
    const int r = k.radius, lo = src.region.ybegin, hi = src.region.yend;
    RowRing rows(2 * r + 1, len);
    int next = std::max(lo, strip.ybegin - r);
    for (int y = strip.ybegin; y < strip.yend; ++y) {
        const Span span = clip_window(y, r, lo, hi);
        for (; next < span.end; ++next)
            direct_row(src, k, next, strip, rows[next]);
        double* o = sums + size_t(y - strip.ybegin) * len;
        std::fill(o, o + len, 0.0);
        for (int yy = span.begin; yy < span.end; ++yy) {
            const double w = k.weights[size_t(yy - y + r)];
            const double* h = rows[yy];
            for (size_t i = 0; i < len; ++i)
                o[i] += w * h[i];
        }
    }
}

}  // namespace

void separable_sums(const PixelBlock& src, const Kernel1D& kernel, SumOrigin origin,
                    const ROI& strip, double* sums)
{
    if (kernel.box)
        box_sums(src, kernel.radius, origin, strip, sums);
    else
        direct_sums(src, kernel, strip, sums);
}

}  // namespace mcdenoise
