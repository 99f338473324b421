// separable_mean.cpp: wide box means by sliding double-precision sums, the
// other kernels by float column-then-row taps, both divided by the weights
// that contributed.
#include "walkers/separable_mean.h"

#include "core/window.h"

#include <algorithm>
#include <cstring>
#include <memory>

namespace mcdenoise {

using OIIO::ImageBuf;
using OIIO::ROI;

Kernel1D box_kernel(int size)
{
    Kernel1D k;
    k.radius = size / 2;
    k.sliding = size > max_direct_box_size;
    k.weights.assign(size_t(size), 1.0f);
    return k;
}

Kernel1D binomial_kernel(int size)
{
    std::vector<double> row(size_t(size), 0.0);
    row[0] = 1.0;
    for (int n = 1; n < size; ++n) {  // next row of Pascal's triangle, halved
        for (int i = n; i >= 1; --i)
            row[size_t(i)] = 0.5 * (row[size_t(i)] + row[size_t(i - 1)]);
        row[0] *= 0.5;
    }
    Kernel1D k;
    k.radius = size / 2;
    k.weights.assign(row.begin(), row.end());
    return k;
}

ROI separable_source_region(const ROI& roi, const Kernel1D& kernel, const ROI& bounds)
{
    ROI grown = roi;
    if (kernel.sliding) {
        const int interval = restart_interval(kernel.radius);
        grown.xbegin = restart_at_or_before(roi.xbegin, bounds.xbegin, interval);
        grown.ybegin = restart_at_or_before(roi.ybegin, bounds.ybegin, interval);
    }
    return grow_and_clip(grown, kernel.radius, bounds);
}

void make_separable_source(PixelBlock block, const ROI& bounds, Kernel1D kernel,
                           int nthreads, SeparableSource& source)
{
    source.kernel    = std::move(kernel);
    source.origin_x  = bounds.xbegin;
    source.origin_y  = bounds.ybegin;
    source.nchannels = block.nchannels;
    source.masked    = needs_finite_mask(block, nthreads);
    source.pixels    = std::make_shared<const PixelBlock>(
        source.masked ? with_finite_mask(block, nthreads) : std::move(block));
}

SeparableSource with_kernel(const SeparableSource& source, Kernel1D kernel)
{
    SeparableSource out = source;
    out.kernel          = std::move(kernel);
    return out;
}

bool load_separable_source(const char* op, ImageBuf& dst, const ImageBuf& beauty,
                           const ROI& roi, Kernel1D kernel, int nthreads,
                           SeparableSource& source)
{
    ROI region     = separable_source_region(roi, kernel, beauty.roi());
    region.chbegin = roi.chbegin;
    region.chend   = roi.chend;
    PixelBlock block;
    if (!read_beauty(op, dst, beauty, region, block))
        return false;
    make_separable_source(std::move(block), beauty.roi(), std::move(kernel), nthreads,
                          source);
    return true;
}

namespace {

// Turns one row of window sums into means: each sum divided by the weights
// that contributed: the mask sums that follow the value sums when the source
// is masked, else the row's geometric weights (the same for every channel of
// a pixel). Windows with no weight give 0 and are counted.
template<class Sum>
class RowMeans {
public:
    RowMeans(int nchannels, bool masked, int width)
        : m_nc(nchannels), m_masked(masked), m_quotients(size_t(width) * nchannels)
    {
    }

    /// `sums`: `width` pixels (at most the row's) of (2 when masked) *
    /// nchannels values; `geometric`: `width` weights, unused when masked.
    /// When `empty_per_pixel` is given, it receives each pixel's count of
    /// empty channels.
    int64_t write(const Sum* sums, const Sum* geometric, int width, float* out,
                  std::ptrdiff_t stride, uint8_t* empty_per_pixel)
    {
        const int nc      = m_nc;
        const size_t n    = size_t(width) * nc;
        int64_t empty     = 0;
        if (m_masked) {
            for (int x = 0; x < width; ++x, sums += 2 * nc, out += stride) {
                int pixel_empty = 0;
                for (int c = 0; c < nc; ++c) {
                    const Sum weight = sums[nc + c];
                    const bool any   = weight > Sum(0);
                    out[c]           = any ? float(sums[c] * (Sum(1) / weight)) : 0.0f;
                    pixel_empty += !any;
                }
                if (empty_per_pixel)
                    empty_per_pixel[x] = uint8_t(std::min(pixel_empty, 255));
                empty += pixel_empty;
            }
            return empty;
        }
        if (empty_per_pixel)
            std::fill(empty_per_pixel, empty_per_pixel + width, uint8_t(0));
        expand(geometric, width);
        float* q = m_quotients.data();
        for (size_t i = 0; i < n; ++i)  // every geometric weight is > 0
            q[i] = float(sums[i] * m_reciprocals[i]);
        if (stride == nc) {
            std::copy(q, q + n, out);
        } else {
            for (int x = 0; x < width; ++x, q += nc, out += stride)
                for (int c = 0; c < nc; ++c)
                    out[c] = q[c];
        }
        return empty;
    }

private:
    // One reciprocal weight per value, rebuilt only when the row's weights
    // change (they are the same for every row whose window is not clipped).
    void expand(const Sum* geometric, int width)
    {
        // Weights are positive: equal values have equal bits (memcmp is SIMD).
        if (m_weights.size() == size_t(width)
            && std::memcmp(m_weights.data(), geometric, sizeof(Sum) * size_t(width)) == 0)
            return;
        m_weights.assign(geometric, geometric + width);
        m_reciprocals.resize(size_t(width) * m_nc);
        for (size_t x = 0; x < size_t(width); ++x)
            std::fill_n(m_reciprocals.begin() + std::ptrdiff_t(x * m_nc), m_nc,
                        Sum(1) / geometric[x]);
    }

    int m_nc;
    bool m_masked;
    std::vector<float> m_quotients;
    std::vector<Sum> m_weights, m_reciprocals;
};

// Wide box means: vertical sums slide down the columns, horizontal sums slide
// along the row, both in double and both restarting from scratch every
// `restart_interval` pixels from the data window's origin.
class SlidingBoxRows {
public:
    SlidingBoxRows(const SeparableSource& src, const ROI& strip)
        : m_src(src), m_strip(strip), m_r(src.kernel.radius),
          m_interval(restart_interval(m_r)), m_channels(src.block().nchannels),
          m_xb(restart_at_or_before(strip.xbegin, src.origin_x, m_interval)),
          m_x0(std::max(src.block().region.xbegin, m_xb - m_r)),
          m_x1(std::min(src.block().region.xend, strip.xend + m_r)),
          m_col(size_t(m_x1 - m_x0) * m_channels), m_sum(size_t(m_channels)),
          m_row(size_t(strip.width()) * m_channels), m_weights(size_t(strip.width())),
          m_means(src.nchannels, src.masked, strip.width())
    {
    }

    int64_t row(int y, Span xs, float* out, std::ptrdiff_t stride, uint8_t* empty_per_pixel)
    {
        const int start = m_col_y == no_row
                              ? restart_at_or_before(y, m_src.origin_y, m_interval)
                              : m_col_y + 1;
        for (int yy = start; yy <= y; ++yy)
            advance_columns(yy);
        horizontal(xs);
        const ROI& reg    = m_src.block().region;
        const double rows = double(clip_window(y, m_r, reg.ybegin, reg.yend).size());
        for (int x = xs.begin; x < xs.end; ++x)
            m_weights[size_t(x - xs.begin)]
                = rows * double(clip_window(x, m_r, reg.xbegin, reg.xend).size());
        const size_t first = size_t(xs.begin - m_strip.xbegin);
        return m_means.write(m_row.data() + first * m_channels, m_weights.data(), xs.size(),
                             out + std::ptrdiff_t(first) * stride, stride,
                             empty_per_pixel ? empty_per_pixel + first : nullptr);
    }

private:
    static constexpr int no_row = INT32_MIN;

    const double* col(int x) const { return m_col.data() + size_t(x - m_x0) * m_channels; }

    void add_row(int y, double sign)
    {
        const float* p = m_src.block().pixel(m_x0, y);
        const size_t n = m_col.size();
        double* c      = m_col.data();
        if (sign > 0)
            for (size_t i = 0; i < n; ++i)
                c[i] += p[i];
        else
            for (size_t i = 0; i < n; ++i)
                c[i] -= p[i];
    }

    void advance_columns(int y)
    {
        const ROI& reg = m_src.block().region;
        if ((y - m_src.origin_y) % m_interval == 0) {
            std::fill(m_col.begin(), m_col.end(), 0.0);
            const Span span = clip_window(y, m_r, reg.ybegin, reg.yend);
            for (int yy = span.begin; yy < span.end; ++yy)
                add_row(yy, 1.0);
        } else {
            if (y + m_r < reg.yend)
                add_row(y + m_r, 1.0);
            if (y - m_r - 1 >= reg.ybegin)
                add_row(y - m_r - 1, -1.0);
        }
        m_col_y = y;
    }

    void horizontal(Span xs)
    {
        switch (m_channels) {
        case 1: return horizontal_for<1>(xs);
        case 2: return horizontal_for<2>(xs);
        case 3: return horizontal_for<3>(xs);
        case 4: return horizontal_for<4>(xs);
        case 6: return horizontal_for<6>(xs);
        case 8: return horizontal_for<8>(xs);
        default: return horizontal_for<0>(xs);
        }
    }

    // Sliding row sums over `xs`, from scratch at each restart point;
    // `FixedC` is the channel count when known at compile time (0:
    // m_channels).
    template<int FixedC>
    void horizontal_for(Span xs)
    {
        const ROI& reg = m_src.block().region;
        const int C    = FixedC ? FixedC : m_channels;
        const int r    = m_r;
        double* s      = m_sum.data();
        const int first = restart_at_or_before(xs.begin, m_src.origin_x, m_interval);
        for (int xa = std::max(m_xb, first); xa < xs.end; xa += m_interval) {
            const int xe    = std::min(xa + m_interval, xs.end);
            const Span span = clip_window(xa, r, reg.xbegin, reg.xend);
            for (int c = 0; c < C; ++c)
                s[c] = 0.0;
            for (int x = span.begin; x < span.end; ++x) {
                const double* v = col(x);
                for (int c = 0; c < C; ++c)
                    s[c] += v[c];
            }
            for (int x = xa; x < xe; ++x) {
                if (x > xa) {
                    if (x + r < reg.xend) {
                        const double* v = col(x + r);
                        for (int c = 0; c < C; ++c)
                            s[c] += v[c];
                    }
                    if (x - r - 1 >= reg.xbegin) {
                        const double* v = col(x - r - 1);
                        for (int c = 0; c < C; ++c)
                            s[c] -= v[c];
                    }
                }
                if (x >= xs.begin) {
                    double* o = m_row.data() + size_t(x - m_strip.xbegin) * C;
                    for (int c = 0; c < C; ++c)
                        o[c] = s[c];
                }
            }
        }
    }

    const SeparableSource& m_src;
    ROI m_strip;
    int m_r, m_interval, m_channels;
    int m_xb, m_x0, m_x1;
    std::vector<double> m_col;
    std::vector<double> m_sum;
    std::vector<double> m_row;      // window sums of the current row
    std::vector<double> m_weights;  // geometric weight of each pixel's window
    RowMeans<double> m_means;
    int m_col_y = no_row;
};

// Tapped means: each row's window columns weighted and summed (float SIMD
// over the whole row), then each pixel's row of column sums weighted.
class TapRows {
public:
    TapRows(const SeparableSource& src, const ROI& strip)
        : m_src(src), m_strip(strip), m_r(src.kernel.radius),
          m_channels(src.block().nchannels),
          m_x0(std::max(src.block().region.xbegin, strip.xbegin - m_r)),
          m_x1(std::min(src.block().region.xend, strip.xend + m_r)),
          m_col(size_t(m_x1 - m_x0) * m_channels),
          m_row(size_t(strip.width()) * m_channels), m_weights(size_t(strip.width())),
          m_means(src.nchannels, src.masked, strip.width())
    {
    }

    int64_t row(int y, Span xs, float* out, std::ptrdiff_t stride, uint8_t* empty_per_pixel)
    {
        const ROI& reg = m_src.block().region;
        const Span ys  = clip_window(y, m_r, reg.ybegin, reg.yend);
        vertical(y, ys, Span { std::max(m_x0, xs.begin - m_r), std::min(m_x1, xs.end + m_r) });
        horizontal(xs);
        const float* w = m_src.kernel.weights.data();
        float column_weight = 0.0f;  // what an all-ones channel sums to
        for (int j = ys.begin; j < ys.end; ++j)
            column_weight += w[j - y + m_r] * 1.0f;
        if (!m_src.masked)
            geometric_weights(column_weight, xs);
        const size_t first = size_t(xs.begin - m_strip.xbegin);
        return m_means.write(m_row.data() + first * m_channels, m_weights.data(), xs.size(),
                             out + std::ptrdiff_t(first) * stride, stride,
                             empty_per_pixel ? empty_per_pixel + first : nullptr);
    }

private:
    // What an all-ones channel sums to at each pixel, in the order the
    // sums are taken; the same for every pixel whose window is not clipped.
    void geometric_weights(float column_weight, Span xs)
    {
        const ROI& reg = m_src.block().region;
        const float* w = m_src.kernel.weights.data();
        float interior = 0.0f;
        for (int i = 0; i <= 2 * m_r; ++i)
            interior += w[i] * column_weight;
        const int in_begin = std::clamp(reg.xbegin + m_r, xs.begin, xs.end);
        const int in_end   = std::clamp(reg.xend - m_r, in_begin, xs.end);
        const auto clipped = [&](int x) {  // windows cut by the region's edge
            const Span window = clip_window(x, m_r, reg.xbegin, reg.xend);
            float weight      = 0.0f;
            for (int i = window.begin; i < window.end; ++i)
                weight += w[i - x + m_r] * column_weight;
            m_weights[size_t(x - xs.begin)] = weight;
        };
        for (int x = xs.begin; x < in_begin; ++x)
            clipped(x);
        std::fill_n(m_weights.data() + (in_begin - xs.begin), in_end - in_begin, interior);
        for (int x = in_end; x < xs.end; ++x)
            clipped(x);
    }

    // The weighted column sums of columns `cols` for row y.
    void vertical(int y, Span ys, Span cols)
    {
        const float* w = m_src.kernel.weights.data();
        const size_t n = size_t(cols.size()) * m_channels;
        float* c       = m_col.data() + size_t(cols.begin - m_x0) * m_channels;
        std::fill(c, c + n, 0.0f);
        for (int j = ys.begin; j < ys.end; ++j) {
            const float wj = w[j - y + m_r];
            const float* p = m_src.block().pixel(cols.begin, j);
            for (size_t i = 0; i < n; ++i)
                c[i] += wj * p[i];
        }
    }

    void horizontal(Span xs)
    {
        const ROI& reg = m_src.block().region;
        const float* w = m_src.kernel.weights.data();
        const int C = m_channels, r = m_r;
        const int in_begin = std::clamp(reg.xbegin + r, xs.begin, xs.end);
        const int in_end   = std::clamp(reg.xend - r, in_begin, xs.end);
        auto edge_pixel = [&](int x) {
            const Span window = clip_window(x, r, reg.xbegin, reg.xend);
            float* o          = m_row.data() + size_t(x - m_strip.xbegin) * C;
            std::fill(o, o + C, 0.0f);
            for (int i = window.begin; i < window.end; ++i) {
                const float* v = m_col.data() + size_t(i - m_x0) * C;
                for (int c = 0; c < C; ++c)
                    o[c] += w[i - x + r] * v[c];
            }
        };
        for (int x = xs.begin; x < in_begin; ++x)
            edge_pixel(x);
        if (in_end > in_begin) {
            float* o       = m_row.data() + size_t(in_begin - m_strip.xbegin) * C;
            const size_t n = size_t(in_end - in_begin) * C;
            std::fill(o, o + n, 0.0f);
            for (int i = 0; i <= 2 * r; ++i) {
                const float wi = w[i];
                const float* v = m_col.data() + size_t(in_begin - r + i - m_x0) * C;
                for (size_t k = 0; k < n; ++k)
                    o[k] += wi * v[k];
            }
        }
        for (int x = in_end; x < xs.end; ++x)
            edge_pixel(x);
    }

    const SeparableSource& m_src;
    ROI m_strip;
    int m_r, m_channels;
    int m_x0, m_x1;
    std::vector<float> m_col;
    std::vector<float> m_row;
    std::vector<float> m_weights;
    RowMeans<float> m_means;
};

}  // namespace

struct SeparableMeanRows::Impl {
    Impl(const SeparableSource& source, const ROI& strip)
    {
        if (source.kernel.sliding)
            sliding.reset(new SlidingBoxRows(source, strip));
        else
            taps.reset(new TapRows(source, strip));
    }
    std::unique_ptr<SlidingBoxRows> sliding;
    std::unique_ptr<TapRows> taps;
};

SeparableMeanRows::SeparableMeanRows(const SeparableSource& source, const ROI& strip)
    : m_strip(strip), m_impl(new Impl(source, strip))
{
}

SeparableMeanRows::~SeparableMeanRows() = default;

int64_t SeparableMeanRows::row(int y, float* out, std::ptrdiff_t stride,
                               uint8_t* empty_per_pixel)
{
    return row(y, Span { m_strip.xbegin, m_strip.xend }, out, stride, empty_per_pixel);
}

int64_t SeparableMeanRows::row(int y, Span xs, float* out, std::ptrdiff_t stride,
                               uint8_t* empty_per_pixel)
{
    return m_impl->sliding ? m_impl->sliding->row(y, xs, out, stride, empty_per_pixel)
                           : m_impl->taps->row(y, xs, out, stride, empty_per_pixel);
}

void separable_mean_strip(const SeparableSource& source, const ROI& strip,
                          ResultPixels& result)
{
    SeparableMeanRows rows(source, strip);
    int64_t empty = 0;
    for (int y = strip.ybegin; y < strip.yend; ++y)
        empty += rows.row(y, result.pixel(strip.xbegin, y), result.pixel_stride(), nullptr);
    result.empty_windows += empty;
}

}  // namespace mcdenoise
