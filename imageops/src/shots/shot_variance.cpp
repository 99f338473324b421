// shot_variance.cpp: the spread of each pixel's colour across the frames
// that agree with the centre there, as the frames' variance.
#include "shots/shot_variance.h"

#include "core/window.h"

#include <algorithm>
#include <array>
#include <vector>

namespace mcdenoise {

using OIIO::ROI;

namespace {

/// How many standard deviations the box means of a neighbour and the
/// centre may differ by.
constexpr float agreement_sigmas = 3.0f;
/// How many times the variance of independent pixels' mean a box mean's
/// variance is taken to be (see shot_variance.h).
constexpr float correlated_pixels = 2.0f;
/// The feature weight (features.h) a neighbour's pixel needs to count.
constexpr float min_feature_weight = 0.25f;

// The boxes of agreement_radius around the pixels of one row y of
// `region`, clipped to the data window `dw`, and the sums they are made
// of: the columns' sums over the box's rows, then their running sums
// along the row (in double), so a box's sum costs two reads whatever the
// radius.
struct RowBoxes {
    ROI cols;  ///< the columns the boxes read: `region` grown, clipped to `dw`
    Span ys;   ///< the boxes' rows
    Span out;  ///< the pixels of the row
    ROI dw;
    std::vector<float> column;
    std::vector<double> running;

    RowBoxes(const ROI& region, const ROI& dw_, int y)
        : cols(grow_and_clip(region, agreement_radius, dw_)),
          ys(clip_window(y, agreement_radius, dw_.ybegin, dw_.yend)),
          out { region.xbegin, region.xend }, dw(dw_)
    {
        column.resize(size_t(cols.width()));
    }

    /// Start a new sum of the columns.
    void clear() { std::fill(column.begin(), column.end(), 0.0f); }

    /// Add to the columns' sums the rows `row(qy)` (a row of values over
    /// `cols`).
    template<class Row>
    void add(Row&& row)
    {
        float* sum = column.data();
        for (int qy = ys.begin; qy < ys.end; ++qy) {
            const float* v = row(qy);
            for (int i = 0; i < cols.width(); ++i)
                sum[i] += v[i];
        }
    }

    /// Add to the columns' sums the rows `row(qy)` minus the rows
    /// `minus(qy)`.
    template<class Row, class Minus>
    void add_difference(Row&& row, Minus&& minus)
    {
        float* sum = column.data();
        for (int qy = ys.begin; qy < ys.end; ++qy) {
            const float* v = row(qy);
            const float* m = minus(qy);
            for (int i = 0; i < cols.width(); ++i)
                sum[i] += v[i] - m[i];
        }
    }

    /// `put(i, mean)` for each pixel i (from 0) of the row: the mean of
    /// what was added over its box.
    template<class Put>
    void means(Put&& put)
    {
        running.resize(column.size() + 1);
        running[0] = 0.0;
        for (size_t i = 0; i < column.size(); ++i)
            running[i + 1] = running[i] + double(column[i]);
        for (int x = out.begin; x < out.end; ++x) {
            const Span xs = clip_window(x, agreement_radius, dw.xbegin, dw.xend);
            const double sum
                = running[size_t(xs.end - cols.xbegin)] - running[size_t(xs.begin - cols.xbegin)];
            put(size_t(x - out.begin), float(sum / (double(ys.size()) * double(xs.size()))));
        }
    }
};

// Per pixel of the row, the squared difference of a neighbour's box mean
// from the centre's, summed over the colour channels, that agreement
// allows: agreement_sigmas^2 times 2 v correlated_pixels / box, v summed
// over the channels (the box mean is linear: one sum for all of them).
void allowed_row(const NlmFrame& centre, RowBoxes& boxes, std::vector<float>& allowed)
{
    const float box = float((2 * agreement_radius + 1) * (2 * agreement_radius + 1));
    boxes.clear();
    for (int c = 0; c < centre.colour->nchannels(); ++c) {
        boxes.add([&](int qy) { return centre.variance->colour.from(c, boxes.cols.xbegin, qy); });
    }
    boxes.means([&](size_t i, float mean) {
        allowed[i] = agreement_sigmas * agreement_sigmas * 2.0f * mean * correlated_pixels / box;
    });
}

// Per pixel of the row, the squared difference of neighbour `f`'s box
// mean from the centre's, summed over the colour channels.
void apart_row(const NlmFrame& centre, const NlmFrame& f, RowBoxes& boxes,
               std::vector<float>& apart)
{
    std::fill(apart.begin(), apart.end(), 0.0f);
    for (int c = 0; c < centre.colour->nchannels(); ++c) {
        boxes.clear();
        boxes.add_difference(
            [&](int qy) { return f.colour->colour.from(c, boxes.cols.xbegin, qy); },
            [&](int qy) { return centre.colour->colour.from(c, boxes.cols.xbegin, qy); });
        boxes.means([&](size_t i, float mean) { apart[i] += mean * mean; });
    }
}

// Per neighbour, whether it agrees with the centre (1 or 0) at each pixel
// of row y of `region`: `agrees[k - 1]`, one value per pixel of the row.
void agreement_row(const std::vector<NlmFrame>& frames,
                   const std::vector<const Plane<float>*>& faithful, const ROI& region,
                   const ROI& dw, int y, std::vector<std::vector<float>>& agrees)
{
    const NlmFrame& centre = frames[0];
    const int n            = region.width();
    const size_t count     = static_cast<size_t>(n);
    RowBoxes boxes(region, dw, y);
    std::vector<float> allowed(count), apart(count), features(count);
    const std::vector<float> no_exponent(count, 0.0f);
    allowed_row(centre, boxes, allowed);
    for (size_t k = 1; k < frames.size(); ++k) {
        const NlmFrame& f = frames[k];
        apart_row(centre, f, boxes, apart);
        centre.features->weights_row(y, region.xbegin, n, 0, 0, no_exponent.data(), 1.0f,
                                     features.data(), *f.features);
        const Plane<float>& put = *faithful[k - 1];
        std::vector<float>& a   = agrees[k - 1];
        a.resize(count);
        for (size_t i = 0; i < count; ++i)
            a[i] = put.at(region.xbegin + int(i), y) > 0.0f && features[i] >= min_feature_weight
                           && apart[i] <= allowed[i]
                       ? 1.0f
                       : 0.0f;
    }
}

}  // namespace

std::vector<Plane<float>> shot_agreement(const std::vector<NlmFrame>& frames,
                                         const std::vector<const Plane<float>*>& faithful,
                                         const ROI& region, const ROI& dw, int nthreads)
{
    std::vector<Plane<float>> out(frames.size() - 1, Plane<float>(region));
    parallel_rows(region, nthreads, [&](int y) {
        std::vector<std::vector<float>> agrees(frames.size() - 1);
        agreement_row(frames, faithful, region, dw, y, agrees);
        for (size_t k = 0; k < agrees.size(); ++k)
            std::copy(agrees[k].begin(), agrees[k].end(), out[k].row(y));
    });
    return out;
}

std::vector<VarianceField> shot_variance(const std::vector<NlmFrame>& frames,
                                         const std::vector<const Plane<float>*>& faithful,
                                         const ROI& region, const ROI& dw, int nthreads)
{
    const bool any = std::any_of(faithful.begin(), faithful.end(), [](const Plane<float>* p) {
        return std::any_of(p->values.begin(), p->values.end(), [](float v) { return v > 0.0f; });
    });
    std::vector<VarianceField> out;
    if (!any || frames.size() < 3)
        return out;
    const int nc  = frames[0].colour->nchannels();
    const auto lw = luminance_weights(nc);
    for (size_t k = 0; k < frames.size(); ++k)
        out.push_back({ Planes<float>(region, nc), Plane<float>(region) });
    parallel_rows(region, nthreads, [&](int y) {
        std::vector<std::vector<float>> agrees(frames.size() - 1);
        agreement_row(frames, faithful, region, dw, y, agrees);
        for (int x = region.xbegin; x < region.xend; ++x) {
            const size_t i = size_t(x - region.xbegin);
            double n       = 1.0;
            for (const std::vector<float>& a : agrees)
                n += a[i];
            std::array<float, feature_colour_channels> spread {};
            for (int c = 0; c < nc && n >= 3.0; ++c) {
                double sum = *frames[0].colour->colour.from(c, x, y), sum2 = sum * sum;
                for (size_t k = 1; k < frames.size(); ++k) {
                    const double v = agrees[k - 1][i] * *frames[k].colour->colour.from(c, x, y);
                    sum += v;
                    sum2 += v * v;
                }
                spread[size_t(c)] = float(std::max(0.0, (sum2 - sum * sum / n) / (n - 1.0)));
            }
            for (size_t k = 0; k < frames.size(); ++k) {
                float lum = 0.0f;
                for (int c = 0; c < nc; ++c) {
                    const float v = std::max(*frames[k].variance->colour.from(c, x, y),
                                             spread[size_t(c)]);
                    *out[k].colour.from(c, x, y) = v;
                    lum += lw[size_t(c)] * lw[size_t(c)] * v;
                }
                out[k].luminance.at(x, y) = lum;
            }
        }
    });
    return out;
}

}  // namespace mcdenoise
