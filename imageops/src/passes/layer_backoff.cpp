// layer_backoff.cpp: a light layer's back-off towards its own values
// where the beauty's weights blurred it, and the error that leaves. The
// window figures are streamed row by row: a few rows of window variances
// per channel, never a plane of them.
#include "passes/layer_backoff.h"

#include "walkers/window_variance.h"

#include <OpenImageIO/imagebufalgo_util.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace mcdenoise {

using OIIO::ImageBuf;
using OIIO::ROI;

namespace {

/// `v`, or 0 where not finite.
float finite_or_zero(float v) { return std::isfinite(v) ? v : 0.0f; }

/// `planes` over `roi`: allocated only when their region differs.
void cover(BackoffPlanes& planes, const ROI& roi)
{
    if (planes.noise.region == roi && !planes.noise.values.empty())
        return;
    for (Plane<float>* p : { &planes.noise, &planes.residual, &planes.mean_square, &planes.level })
        *p = Plane<float>(roi);
}

/// The window figures of one strip of output rows, streamed: three rows of
/// window variances per channel of e and of the average, each row made
/// once from box sums over the blocks' rows (windows clipped to the
/// average's region `g`), and the figures of each output row read from
/// them.
class FigureRows {
public:
    FigureRows(const PixelBlock& average, const PixelBlock& layer, const Plane<float>& scale,
               const ROI& roi)
        : m_average(average)
        , m_layer(layer)
        , m_scale(scale)
        , m_g(average.region)
        , m_nc(average.nchannels)
        , m_cols { std::max(m_g.xbegin, roi.xbegin - 1), std::min(m_g.xend, roi.xend + 1) }
        , m_reads { std::max(m_g.xbegin, m_cols.begin - 1), std::min(m_g.xend, m_cols.end + 1) }
        , m_e_sums(m_reads)
        , m_a_sums(m_reads)
        , m_e(size_t(m_reads.size()))
        , m_a(size_t(m_reads.size()))
        , m_rows(size_t(3 * (2 * m_nc + 1) * m_cols.size()))
        , m_smallest(size_t(m_cols.size()))
        , m_roi_cols { roi.xbegin, roi.xend }
    {
    }

    /// Make sure the variance rows y - 1 .. y + 1 (those within `g`) are
    /// made, each once over the strip.
    void prepare(int y)
    {
        for (int r = std::max(m_g.ybegin, y - 1); r <= std::min(m_g.yend - 1, y + 1); ++r)
            if (r > m_last) {
                make_row(r);
                m_last = r;
            }
    }

    /// Row y's figures over `roi`'s columns (after `prepare(y)`): s2 from
    /// the windows into `noise`, t2 into `residual`, m2 into `mean_square`.
    void row(int y, float* noise, float* residual, float* mean_square)
    {
        const Span ys   = clip_window(y, 1, m_g.ybegin, m_g.yend);
        const int width = m_roi_cols.size();
        std::fill(noise, noise + width, 0.0f);
        std::fill(residual, residual + width, 0.0f);
        for (int q = 0; q < 2 * m_nc; ++q) {
            // the smallest over the window's rows, then over its columns
            smallest_of_rows(
                ys.size(), m_cols.size(), [&](int k) { return variance_row(q, ys.begin + k); },
                m_smallest.data());
            float* sum = q < m_nc ? noise : residual;
            window_minima(m_smallest.data(), m_cols, m_roi_cols, m_g.xbegin, m_g.xend,
                          [&](int x, float m) {
                              sum[x - m_roi_cols.begin] += m / smallest_window_bias;
                          });
        }
        const float* squares = variance_row(2 * m_nc, y) + (m_roi_cols.begin - m_cols.begin);
        std::copy(squares, squares + width, mean_square);
    }

private:
    /// Row `r`'s window variances of quantity q (e of channel q, or the
    /// average of channel q - nc), or with q = 2 nc the window mean of
    /// |e|^2 summed over channels.
    float* variance_row(int q, int r)
    {
        const int slot = ((r % 3) + 3) % 3;
        return m_rows.data() + size_t((q * 3 + slot) * m_cols.size());
    }
    const float* variance_row(int q, int r) const
    {
        return const_cast<FigureRows*>(this)->variance_row(q, r);
    }

    /// Row `qy`'s values of channel c over the read columns: e into
    /// `m_e`, the average into `m_a` (0 where not finite).
    void load_row(int qy, int c)
    {
        const float* a    = m_average.pixel(m_reads.begin, qy) + c;
        const float* k    = m_layer.pixel(m_reads.begin, qy) + c;
        const float* s    = m_scale.from(m_reads.begin, qy);
        const size_t an   = size_t(m_average.nchannels), kn = size_t(m_layer.nchannels);
        for (size_t i = 0; i < m_e.size(); ++i) {
            m_a[i] = finite_or_zero(a[i * an]);
            m_e[i] = finite_or_zero(a[i * an] - k[i * kn] * s[i]);
        }
    }

    /// The variance rows of row `r`, from the blocks' rows r - 1 .. r + 1.
    void make_row(int r)
    {
        const Span ys     = clip_window(r, 1, m_g.ybegin, m_g.yend);
        float* square_row = variance_row(2 * m_nc, r);
        std::fill(square_row, square_row + m_cols.size(), 0.0f);
        for (int c = 0; c < m_nc; ++c) {
            m_e_sums.clear();
            m_a_sums.clear();
            for (int qy = ys.begin; qy < ys.end; ++qy) {
                load_row(qy, c);
                m_e_sums.add_row(m_e.data());
                m_a_sums.add_row(m_a.data());
            }
            float* e_row = variance_row(c, r);
            float* a_row = variance_row(m_nc + c, r);
            window_row(m_e_sums, m_cols, m_g.xbegin, m_g.xend,
                       [&](int x, double sum, double square, int columns) {
                           const int n    = columns * ys.size();
                           const size_t o = size_t(x - m_cols.begin);
                           e_row[o]       = sample_variance(sum, square, n);
                           square_row[o] += float(square / n);
                       });
            window_row(m_a_sums, m_cols, m_g.xbegin, m_g.xend,
                       [&](int x, double sum, double square, int columns) {
                           a_row[x - m_cols.begin] = sample_variance(sum, square, columns * ys.size());
                       });
        }
    }

    const PixelBlock& m_average;
    const PixelBlock& m_layer;
    const Plane<float>& m_scale;
    ROI m_g;
    int m_nc;
    Span m_cols;   ///< the columns whose variances the output's minima read
    Span m_reads;  ///< the columns their windows read
    ColumnSums m_e_sums, m_a_sums;
    std::vector<float> m_e, m_a;  ///< one row's values of one channel
    std::vector<float> m_rows;
    std::vector<float> m_smallest;  ///< one quantity's minima over the window's rows
    Span m_roi_cols;
    int m_last = std::numeric_limits<int>::min();
};

/// |average|^2 at (x, y), summed over channels (non-finite values as 0).
float level_at(const PixelBlock& average, int x, int y)
{
    const float* a = average.pixel(x, y);
    float sum      = 0.0f;
    for (int c = 0; c < average.nchannels; ++c)
        sum += finite_or_zero(a[c]) * finite_or_zero(a[c]);
    return sum;
}

/// The median over every `median_stride`-th pixel of `roi` in x and y (of
/// the data window's grid) of noise / level where the level is above 0 (0
/// where it is 0 everywhere): the layer's typical relative noise.
float median_relative_noise(const Plane<float>& noise, const Plane<float>& level, const ROI& roi)
{
    std::vector<float> ratios;
    for (int y = roi.ybegin; y < roi.yend; ++y) {
        if (y % median_stride != 0)
            continue;
        for (int x = roi.xbegin; x < roi.xend; ++x)
            if (x % median_stride == 0 && level.at(x, y) > 0.0f)
                ratios.push_back(noise.at(x, y) / level.at(x, y));
    }
    if (ratios.empty())
        return 0.0f;
    const auto middle = ratios.begin() + std::ptrdiff_t(ratios.size() / 2);
    std::nth_element(ratios.begin(), middle, ratios.end());
    return *middle;
}

/// The figures of an average beside the values it averaged (times the
/// split's scale) into `planes` over `roi`; returns `relative_noise_spread`
/// times the median relative noise.
float fit_average(const PixelBlock& average, const PixelBlock& layer, const Plane<float>& scale,
                  const ROI& roi, int nthreads, BackoffPlanes& planes)
{
    cover(planes, roi);
    ROI rows    = roi;
    rows.chbegin = 0;
    rows.chend   = 1;
    OIIO::ImageBufAlgo::parallel_image(rows, nthreads, [&](ROI strip) {
        FigureRows figures(average, layer, scale, roi);
        for (int y = strip.ybegin; y < strip.yend; ++y) {
            figures.prepare(y);
            size_t i = pixel_offset(roi, roi.xbegin, y);
            figures.row(y, &planes.noise.values[i], &planes.residual.values[i],
                        &planes.mean_square.values[i]);
            for (int x = roi.xbegin; x < roi.xend; ++x, ++i)
                planes.level.values[i] = level_at(average, x, y);
        }
    });
    return relative_noise_spread * median_relative_noise(planes.noise, planes.level, roi);
}

}  // namespace

void back_off_layer(ImageBuf& result, const PixelBlock& average, const PixelBlock& layer,
                    const Plane<float>& scale, int nthreads, BackoffPlanes& planes,
                    Plane<float>& error)
{
    const ROI roi                   = result.roi();
    const float most_relative_noise = fit_average(average, layer, scale, roi, nthreads, planes);
    const int nc = average.nchannels;
    error        = Plane<float>(roi);
    parallel_rows(roi, nthreads, [&](int y) {
        float* out = static_cast<float*>(result.pixeladdr(roi.xbegin, y));
        size_t i   = pixel_offset(roi, roi.xbegin, y);
        for (int x = roi.xbegin; x < roi.xend; ++x, ++i, out += nc) {
            const float s2 = std::min(planes.noise.at(x, y), most_relative_noise * planes.level.at(x, y));
            const float t2    = std::min(planes.residual.at(x, y), s2);
            const float m2    = planes.mean_square.at(x, y);
            const float bias2 = std::max(0.0f, m2 - s2);
            const float a     = m2 > 0.0f ? std::clamp(1.0f - s2 / m2, 0.0f, 1.0f) : 0.0f;
            const float* avg  = average.pixel(x, y);
            const float* kept = layer.pixel(x, y);
            const float s     = scale.at(x, y);
            for (int c = 0; c < nc; ++c)
                out[c] -= a * finite_or_zero(avg[c] - kept[c] * s);
            error.values[i] = a * a * s2 + (1.0f - a) * (1.0f - a) * (bias2 + t2);
        }
    });
}

}  // namespace mcdenoise
