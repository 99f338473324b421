// nlmeans.cpp: non-local means with variance-normalised patch distances
// (Rousselle, Knaus & Zwicker 2012) and feature weights (Rousselle, Manzi &
// Zwicker 2013). One search offset at a time, a chunk of rows at a time:
// the per-pixel distance plane of that offset, its box sums over the patch
// (rows, then columns, in a fixed order), the weights, the sums.
#include <mcdenoise/nlmeans.h>

#include "core/operation.h"
#include "core/window.h"
#include "features/feature_field.h"
#include "features/nlmeans_frames.h"
#include "features/nlmeans_layers.h"
#include "features/weighted_sums.h"
#include "walkers/offset_walk.h"

#include <OpenImageIO/imagebufalgo_util.h>
#include <OpenImageIO/simd.h>

#include <algorithm>

namespace mcdenoise {

using OIIO::ImageBuf;
using OIIO::ROI;

namespace {

// Rows filtered together: the distance planes of a chunk carry 2 f rows of
// overlap, so the chunk is a few times taller than any patch.
constexpr int chunk_rows = 16;
// Guard of the distance's denominator (Rousselle et al. 2012, eq. 9).
constexpr float distance_guard = 1e-10f;

// What every chunk reads: the frames' windows, the filtered frame's first.
struct NlmInputs {
    const std::vector<NlmFrame>& frames;
    const ColourField& colour;      // the filtered pixels' patches
    const VarianceField& variance;  // and their variance
    ROI dw;
    int f;
    float k2;  // strength^2
};

// One row of colour and variance planes at p and at q = p + o, per channel.
struct DistanceRows {
    const float* u_p[feature_colour_channels];
    const float* u_q[feature_colour_channels];
    const float* v_p[feature_colour_channels];
    const float* v_q[feature_colour_channels];
};

// d[i] = the mean over the NC colour channels of the variance-normalised
// distance of pixel i of the p rows and pixel i of the q rows (Rousselle et
// al. 2012, eq. 9), all channels in one pass, eight lanes at a time (the
// tail through the same lane-wise arithmetic, loaded and stored in part).
template<int NC>
void distance_row(const DistanceRows& rows, float k2, float channel_mean, int m, float* d)
{
    using OIIO::simd::vfloat8;
    const vfloat8 guard(distance_guard), k(k2), mean(channel_mean);
    // The distances of eight pixels, their rows read by `load`.
    const auto distances = [&](auto&& load) {
        vfloat8 sum(0.0f);
        for (int c = 0; c < NC; ++c) {
            const vfloat8 a = load(rows.v_p[c]), b = load(rows.v_q[c]);
            const vfloat8 t = load(rows.u_p[c]) - load(rows.u_q[c]);
            sum = sum + (t * t - (a + OIIO::simd::min(a, b))) / (guard + k * (a + b));
        }
        return sum * mean;
    };
    for_each_lane_block(m, d, [&](int, auto&& load) { return distances(load); });
}

// Number of n in [-f, f] with both p + n and p + d + n in [lo, hi).
inline int patch_count(int p, int d, int f, int lo, int hi)
{
    const int a = std::max(-f, std::max(lo - p, lo - p - d));
    const int b = std::min(f, std::min(hi - 1 - p, hi - 1 - p - d));
    return b - a + 1;
}

// The rows `frame_chunk` works in, kept from call to call.
struct ChunkScratch {
    std::vector<float> dist, column, e, w, cx;

    // Sized for distance rows of `pw` by `ph` and `n` pixels a row.
    void size(int pw, int ph, int n)
    {
        dist.resize(size_t(pw) * size_t(ph));
        column.resize(size_t(pw));
        e.resize(size_t(n));
        w.resize(size_t(n));
        cx.resize(size_t(n));
    }
};

// The weights of frame `q`'s window for rows [y0, y1), columns
// [x0, x0 + n) of the ROI, offset by offset: `sink(y, w, dx, dy, i0, i1)`
// takes the weights w[i], i in [i0, i1), of the pixels (x0 + i, y) for
// their neighbours (x0 + i + dx, y + dy).
template<class Sink>
void frame_chunk(const NlmInputs& in, const NlmFrame& q, int y0, int y1, int x0, int n,
                 ChunkScratch& scratch, Sink&& sink)
{
    const ROI& dw     = in.dw;
    const int r = q.search_radius, f = in.f;
    const int pw = n + 2 * f;          // distance rows: x from x0 - f
    const int ph = (y1 - y0) + 2 * f;  // rows from y0 - f
    const int nc = in.colour.nchannels();
    const float channel_mean = 1.0f / float(nc);
    scratch.size(pw, ph, n);
    std::vector<float>& dist = scratch.dist;
    std::vector<float>& column = scratch.column;
    std::vector<float>& e = scratch.e;
    std::vector<float>& w = scratch.w;
    std::vector<float>& cx = scratch.cx;
    for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx) {
            for (int i = 0; i < n; ++i)
                cx[i] = float(patch_count(x0 + i, dx, f, dw.xbegin, dw.xend));
            // Per-pixel distances d(x, x + o), 0 where either is outside.
            std::fill(dist.begin(), dist.end(), 0.0f);
            const int xa = std::max({ dw.xbegin, x0 - f, dw.xbegin - dx });
            const int xb = std::min({ dw.xend, x0 + n + f, dw.xend - dx });
            for (int yy = std::max(dw.ybegin, y0 - f); yy < std::min(dw.yend, y1 + f); ++yy) {
                if (yy + dy < dw.ybegin || yy + dy >= dw.yend || xa >= xb)
                    continue;
                float* d = dist.data() + size_t(yy - (y0 - f)) * pw + (xa - (x0 - f));
                const int m = xb - xa;
                DistanceRows rows;
                for (int c = 0; c < nc; ++c) {
                    rows.u_p[c] = in.colour.colour.from(c, xa, yy);
                    rows.u_q[c] = q.colour->colour.from(c, xa + dx, yy + dy);
                    rows.v_p[c] = in.variance.colour.from(c, xa, yy);
                    rows.v_q[c] = q.variance->colour.from(c, xa + dx, yy + dy);
                }
                if (nc == 3)
                    distance_row<3>(rows, in.k2, channel_mean, m, d);
                else if (nc == 2)
                    distance_row<2>(rows, in.k2, channel_mean, m, d);
                else
                    distance_row<1>(rows, in.k2, channel_mean, m, d);
            }
            for (int y = y0; y < y1; ++y) {
                const Offset o = clip_offset(dx, dy, 1, x0, n, dw);
                if (y + dy < dw.ybegin || y + dy >= dw.yend || o.count() <= 0)
                    continue;
                const int i0 = o.i0, i1 = o.i1;
                if (q.own && o.centre()) {
                    std::fill(w.begin() + i0, w.begin() + i1, 1.0f);
                    sink(y, w.data(), dx, dy, i0, i1);
                    continue;
                }
                // Patch sums: down the rows, then along the columns, each
                // term in a fixed order; then the mean over the patch pixels
                // inside the data window.
                std::fill(column.begin(), column.end(), 0.0f);
                for (int t = 0; t <= 2 * f; ++t) {
                    const float* d = dist.data() + size_t(y - y0 + t) * pw;
                    for (int i = 0; i < pw; ++i)
                        column[i] += d[i];
                }
                std::fill(e.begin() + i0, e.begin() + i1, 0.0f);
                for (int t = 0; t <= 2 * f; ++t)
                    for (int i = i0; i < i1; ++i)
                        e[i] += column[size_t(i + t)];
                const float cy = float(patch_count(y, dy, f, dw.ybegin, dw.yend));
                for (int i = i0; i < i1; ++i)
                    e[i] = std::max(0.0f, e[i] / (cy * cx[i]));
                q.centre_features->weights_row(y, x0 + i0, i1 - i0, dx, dy, e.data() + i0,
                                               1.0f, w.data() + i0, *q.features);
                if (q.usable) {
                    const float* u = q.usable->from(x0 + dx, y + dy);
                    for (int i = i0; i < i1; ++i)
                        w[i] *= u[i];
                }
                sink(y, w.data(), dx, dy, i0, i1);
            }
        }
}

// The weight rows of one search row (one dy) for each row of a chunk, so
// the sums take them in one pass (`WeightedSums::add_rows`).
class WeightBatch {
public:
    WeightBatch(int rows, int per_row, int n)
        : m_per_row(per_row)
        , m_width((n + 7) / 8 * 8)
        , m_weights(size_t(rows) * size_t(per_row) * size_t(m_width))
        , m_rows(size_t(rows))
    {
    }

    // Hold a copy of the weights w[i0, i1) of row `r` for (qx0 + i, qy).
    void put(int r, const float* w, int qx0, int qy, int i0, int i1)
    {
        std::vector<WeightRow>& held = m_rows[size_t(r)];
        float* copy = m_weights.data()
                      + (size_t(r) * size_t(m_per_row) + held.size()) * size_t(m_width);
        std::copy(w + i0, w + i1, copy + i0);
        held.push_back({ copy, qx0, qy, i0, i1 });
    }

    // Add every held row to its sums, in the order held, and let go of them.
    void flush(std::vector<WeightedSums>& sums, const SumSource& values)
    {
        for (size_t r = 0; r < m_rows.size(); ++r) {
            sums[r].add_rows(m_rows[r].data(), int(m_rows[r].size()), values);
            m_rows[r].clear();
        }
    }

private:
    int m_per_row, m_width;
    std::vector<float> m_weights;
    std::vector<std::vector<WeightRow>> m_rows;
};

// The value channels of `target`.
int value_end(const NlmTarget& target)
{
    return target.value_begin + target.result->roi.nchannels();
}

// Whether `tap` names any pixel of rows [y0, y1), columns [x0, x0 + n).
bool taps_chunk(const WeightTap* tap, int y0, int y1, int x0, int n)
{
    if (!tap)
        return false;
    for (int y = y0; y < y1; ++y) {
        const int32_t* k = tap->index.from(x0, y);
        if (std::any_of(k, k + n, [](int32_t v) { return v >= 0; }))
            return true;
    }
    return false;
}

// Rows [y0, y1), columns [x0, x0 + n) of the ROI, into every target; the
// own frame's weights of the pixels `tap` names, into it.
void nlmeans_chunk(const NlmInputs& in, int y0, int y1, int x0, int n,
                   const std::vector<NlmTarget>& targets, const WeightTap* tap)
{
    int c0 = targets.front().value_begin, c1 = value_end(targets.front());
    for (const NlmTarget& t : targets) {
        c0 = std::min(c0, t.value_begin);
        c1 = std::max(c1, value_end(t));
    }
    std::vector<WeightedSums> sums;
    for (int y = y0; y < y1; ++y)
        sums.emplace_back(c0, c1, n, in.frames.front().values->masked());
    ChunkScratch scratch;
    const bool tapped = taps_chunk(tap, y0, y1, x0, n);
    for (const NlmFrame& q : in.frames) {
        WeightBatch batch(y1 - y0, 2 * q.search_radius + 1, n);
        int batch_dy = q.search_radius + 1;
        const int side = 2 * q.search_radius + 1;
        frame_chunk(in, q, y0, y1, x0, n, scratch,
                    [&](int y, const float* w, int dx, int dy, int i0, int i1) {
                        if (dy != batch_dy)
                            batch.flush(sums, *q.values);
                        batch_dy = dy;
                        batch.put(y - y0, w, x0 + dx, y + dy, i0, i1);
                        if (!tapped || !q.own)
                            return;
                        const int32_t* k = tap->index.from(x0, y);
                        const size_t at  = size_t(dy + q.search_radius) * size_t(side)
                                          + size_t(dx + q.search_radius);
                        for (int i = i0; i < i1; ++i)
                            if (k[i] >= 0)
                                tap->weights[size_t(k[i]) * size_t(side) * size_t(side) + at] = w[i];
                    });
        batch.flush(sums, *q.values);
    }
    for (const NlmTarget& t : targets) {
        int64_t empty = 0;
        for (int y = y0; y < y1; ++y)
            empty += sums[size_t(y - y0)].write(t.result->pixel(x0, y),
                                                t.result->pixel_stride(), t.value_begin,
                                                value_end(t));
        t.result->empty_windows += empty;
    }
}

// What `nlmeans` and `nlmeans_layers` check and read before filtering:
// the arguments, the ROI (resolved) and the feature inputs of `beauty`.
bool load_nlmeans(const char* op, ImageBuf& dst, const ImageBuf& beauty, const Guides& guides,
                  int search_radius, int patch_radius, float strength,
                  const FeatureSigmas& sigmas, ROI& roi, int nthreads, FeatureInputs& fin)
{
    if (search_radius < 0 || search_radius > max_nlmeans_search_radius) {
        dst.errorfmt("{}: search_radius must be between 0 and {}, got {}", op,
                     max_nlmeans_search_radius, search_radius);
        return false;
    }
    if (patch_radius < 0 || patch_radius > max_nlmeans_patch_radius) {
        dst.errorfmt("{}: patch_radius must be between 0 and {}, got {}", op,
                     max_nlmeans_patch_radius, patch_radius);
        return false;
    }
    if (!(strength > 0.0f)) {
        dst.errorfmt("{}: strength must be > 0, got {}", op, strength);
        return false;
    }
    if (!resolve_roi(op, dst, beauty, roi) || !check_feature_guides(op, dst, guides, roi))
        return false;
    const ROI dw      = beauty.roi();
    const ROI search  = grow_and_clip(roi, search_radius, dw);
    const ROI patches = grow_and_clip(roi, search_radius + patch_radius, dw);
    return load_feature_inputs(op, dst, beauty, guides, sigmas, search, patches, nthreads, fin);
}

// The filtered frame's own window over `fin`.
std::vector<NlmFrame> own_frame(const FeatureInputs& fin, int search_radius)
{
    return { { &fin.colour, &fin.variance, &fin.features, &fin.features, &fin.values, nullptr,
               search_radius, true } };
}

// Append the planes of `more` (over the same region) to `values`, with a
// finite mask for every plane when either has one.
void append_values(SumSource& values, SumSource&& more)
{
    const auto ones = [](SumSource& s) {
        if (!s.masked())
            for (size_t c = 0; c < s.values.size(); ++c)
                s.finite.emplace_back(plane_size(s.region), 1.0f);
    };
    if (values.masked() || more.masked()) {
        ones(values);
        ones(more);
    }
    for (size_t c = 0; c < more.values.size(); ++c) {
        values.values.push_back(std::move(more.values[c]));
        if (more.masked())
            values.finite.push_back(std::move(more.finite[c]));
    }
}

}  // namespace

bool nlmeans(ImageBuf& dst, const ImageBuf& beauty, const Guides& guides, int search_radius,
             int patch_radius, float strength, const FeatureSigmas& sigmas, ROI roi,
             int nthreads)
{
    const char* op = "nlmeans";
    FeatureInputs fin;
    if (!load_nlmeans(op, dst, beauty, guides, search_radius, patch_radius, strength, sigmas, roi,
                      nthreads, fin))
        return false;
    return nlmeans_frames(op, dst, beauty,
                          { &beauty, guides.object_id, guides.normal, guides.depth,
                            guides.albedo, guides.variance },
                          own_frame(fin, search_radius), fin.colour, fin.variance, patch_radius,
                          strength, roi, nthreads);
}

bool nlmeans_layers(ImageBuf& dst, std::vector<ImageBuf>& dst_layers, const ImageBuf& beauty,
                    const std::vector<const ImageBuf*>& layers, std::vector<SumSource>&& values,
                    const Guides& guides, int search_radius, int patch_radius, float strength,
                    const FeatureSigmas& sigmas, ROI roi, int nthreads, const WeightTap* tap)
{
    const char* op = "nlmeans";
    FeatureInputs fin;
    if (!load_nlmeans(op, dst, beauty, guides, search_radius, patch_radius, strength, sigmas, roi,
                      nthreads, fin))
        return false;
    std::vector<ResultPixels> results(layers.size() + 1);
    std::vector<NlmTarget> targets;
    if (!begin_result(op, dst, beauty,
                      { &beauty, guides.object_id, guides.normal, guides.depth, guides.albedo,
                        guides.variance },
                      roi, results[0]))
        return false;
    targets.push_back({ &results[0], roi.chbegin });
    dst_layers.resize(layers.size());
    for (size_t i = 0; i < layers.size(); ++i) {
        ROI layer_roi    = roi;
        layer_roi.chbegin = 0;
        layer_roi.chend   = layers[i]->nchannels();
        if (!begin_result(op, dst_layers[i], *layers[i], { layers[i] }, layer_roi,
                          results[i + 1])) {
            dst.errorfmt("{}", dst_layers[i].geterror());
            return false;
        }
        targets.push_back({ &results[i + 1], fin.values.nchannels() });
        append_values(fin.values, std::move(values[i]));
    }
    nlmeans_frames(own_frame(fin, search_radius), fin.colour, fin.variance, beauty.roi(),
                   patch_radius, strength, nthreads, targets, tap);
    for (size_t i = 0; i < layers.size(); ++i)
        if (!finish_result(op, dst_layers[i], results[i + 1])) {
            dst.errorfmt("{}", dst_layers[i].geterror());
            return false;
        }
    return finish_result(op, dst, results[0]);
}

void nlmeans_frames(const std::vector<NlmFrame>& frames, const ColourField& colour,
                    const VarianceField& variance, const ROI& dw, int patch_radius,
                    float strength, int nthreads, ResultPixels& result)
{
    nlmeans_frames(frames, colour, variance, dw, patch_radius, strength, nthreads,
                   { { &result, result.roi.chbegin } });
}

void nlmeans_frames(const std::vector<NlmFrame>& frames, const ColourField& colour,
                    const VarianceField& variance, const ROI& dw, int patch_radius,
                    float strength, int nthreads, const std::vector<NlmTarget>& targets,
                    const WeightTap* tap)
{
    const ROI& roi = targets.front().result->roi;
    const NlmInputs in { frames, colour, variance, dw, patch_radius, strength * strength };
    OIIO::ImageBufAlgo::parallel_image(roi, nthreads, [&](ROI strip) {
        const FlushDenormals flush;
        for (int y = strip.ybegin; y < strip.yend; y += chunk_rows)
            for_each_segment(strip.xbegin, strip.xend, [&](int x0, int n) {
                nlmeans_chunk(in, y, std::min(strip.yend, y + chunk_rows), x0, n, targets,
                              tap);
            });
    });
}

void match_weights(const NlmFrame& q, const ColourField& colour, const VarianceField& variance,
                   const ROI& dw, int patch_radius, float strength, int nthreads,
                   Plane<float>& w)
{
    const ROI region = w.region;
    NlmFrame at_pixel      = q;
    at_pixel.search_radius = 0;
    const std::vector<NlmFrame> frames { at_pixel };
    const NlmInputs in { frames, colour, variance, dw, patch_radius,
                         strength * strength };
    std::fill(w.values.begin(), w.values.end(), 0.0f);
    OIIO::ImageBufAlgo::parallel_image(region, nthreads, [&](ROI strip) {
        const FlushDenormals flush;
        ChunkScratch scratch;
        for (int y = strip.ybegin; y < strip.yend; y += chunk_rows)
            for_each_segment(strip.xbegin, strip.xend, [&](int x0, int n) {
                frame_chunk(in, at_pixel, y, std::min(strip.yend, y + chunk_rows), x0, n, scratch,
                            [&](int row, const float* wr, int, int, int i0, int i1) {
                                std::copy(wr + i0, wr + i1, w.from(x0 + i0, row));
                            });
            });
    });
}

void window_weights(const NlmFrame& frame, const ColourField& colour,
                    const VarianceField& variance, const ROI& dw, int patch_radius,
                    float strength, const std::vector<PixelXY>& pixels, int nthreads,
                    std::vector<float>& weights)
{
    const int side     = 2 * frame.search_radius + 1;
    const size_t count = size_t(side) * size_t(side);
    weights.assign(pixels.size() * count, 0.0f);
    const std::vector<NlmFrame> frames { frame };
    const NlmInputs in { frames, colour, variance, dw, patch_radius, strength * strength };
    OIIO::ImageBufAlgo::parallel_image(ROI(0, int(pixels.size()), 0, 1), nthreads, [&](ROI part) {
        const FlushDenormals flush;
        ChunkScratch scratch;
        for (int k = part.xbegin; k < part.xend; ++k) {
            const PixelXY p = pixels[size_t(k)];
            float* out      = weights.data() + size_t(k) * count;
            frame_chunk(in, frame, p.y, p.y + 1, p.x, 1, scratch,
                        [&](int, const float* w, int dx, int dy, int i0, int i1) {
                            if (i0 < i1)
                                out[size_t(dy + frame.search_radius) * size_t(side)
                                    + size_t(dx + frame.search_radius)] = w[0];
                        });
        }
    });
}

bool nlmeans_frames(const char* op, ImageBuf& dst, const ImageBuf& like,
                    std::initializer_list<const ImageBuf*> inputs,
                    const std::vector<NlmFrame>& frames, const ColourField& colour,
                    const VarianceField& variance, int patch_radius, float strength,
                    const ROI& roi, int nthreads)
{
    ResultPixels result;
    if (!begin_result(op, dst, like, inputs, roi, result))
        return false;
    nlmeans_frames(frames, colour, variance, like.roi(), patch_radius, strength, nthreads,
                   result);
    return finish_result(op, dst, result);
}

ImageBuf nlmeans(const ImageBuf& beauty, const Guides& guides, int search_radius,
                 int patch_radius, float strength, const FeatureSigmas& sigmas, ROI roi,
                 int nthreads)
{
    return value_form([&](ImageBuf& dst) {
        return nlmeans(dst, beauty, guides, search_radius, patch_radius, strength, sigmas,
                       roi, nthreads);
    });
}

}  // namespace mcdenoise
