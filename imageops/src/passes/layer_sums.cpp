// layer_sums.cpp: the denoised layers' rebuild corrected to the denoised
// beauty where the raw layers rebuilt the raw beauty.
#include "passes/layer_sums.h"

#include "core/window.h"
#include "features/feature_field.h"

#include <algorithm>
#include <cmath>

namespace mcdenoise {

using OIIO::ImageBuf;
using OIIO::ROI;

namespace {

/// Term `t`'s colour at (x, y), channel c: 1 without a colour pass.
float colour_at(const SumTerm& t, int x, int y, int c)
{
    return t.colour ? t.colour->pixel(x, y)[c] : 1.0f;
}

/// True if the raw terms rebuild the raw beauty at (x, y) in every one of
/// the `nc` colour channels.
bool rebuilds(const PixelBlock& raw, const std::vector<SumTerm>& terms, int x, int y, int nc)
{
    for (int c = 0; c < nc; ++c) {
        const float b = raw.pixel(x, y)[c];
        double sum = 0.0, size = std::fabs(double(b));
        for (const SumTerm& t : terms) {
            const double term = double(colour_at(t, x, y, c)) * double(t.raw->pixel(x, y)[c]);
            sum += term;
            size += std::fabs(term);
        }
        if (!std::isfinite(sum) || !std::isfinite(b)
            || std::fabs(sum - double(b)) > double(pixel_rebuild_tolerance) * size)
            return false;
    }
    return true;
}

/// One pixel's term in one channel: its value, colour and weight, and
/// the bounds a share may move it to.
struct Share {
    float* value;
    float colour;
    float weight;
    float low;
    float high;
};

/// A share's weight when every share's own weight is 0: its part of the
/// rebuild, |colour x value| (a term with no light there takes none).
double fallback_weight(const Share& s) { return std::fabs(double(s.colour) * double(*s.value)); }

/// Give `delta` (in the beauty's units) to `shares` in proportion to their
/// weights (to `fallback_weight` when every weight is 0, equal shares when
/// that is 0 too), each share divided by its colour; a term a share would
/// move past one of its bounds stops there and the rest goes to the
/// others. Returns what none could take.
double share_out(double delta, std::vector<Share>& shares)
{
    while (delta != 0.0 && !shares.empty()) {
        double total = 0.0, fallback_total = 0.0;
        for (const Share& s : shares) {
            total += double(s.weight);
            fallback_total += fallback_weight(s);
        }
        const int rule = total > 0.0 ? 0 : fallback_total > 0.0 ? 1 : 2;
        const double sum = rule == 0 ? total : rule == 1 ? fallback_total : double(shares.size());
        const auto target = [&](const Share& s) {
            const double w = rule == 0 ? double(s.weight) : rule == 1 ? fallback_weight(s) : 1.0;
            return double(*s.value) + delta * w / sum / double(s.colour);
        };
        bool stopped = false;
        for (size_t k = 0; k < shares.size();) {
            Share& s        = shares[k];
            const double to = target(s);
            if (to >= double(s.low) && to <= double(s.high)) {
                ++k;
                continue;
            }
            const float bound = to < double(s.low) ? s.low : s.high;
            delta -= (double(bound) - double(*s.value)) * double(s.colour);
            *s.value = bound;
            shares.erase(shares.begin() + std::ptrdiff_t(k));
            stopped = true;
        }
        if (stopped)
            continue;
        for (Share& s : shares)
            *s.value = float(target(s));
        return 0.0;
    }
    return delta;
}

/// One row's scratch space: where each term's result row starts, the
/// shares of a pixel's terms unbounded but for min(0, value) and weighted
/// by their part of the rebuild, and the shares given out in one round.
struct RowShares {
    std::vector<float*> rows;
    std::vector<Share> terms;
    std::vector<Share> round;
};

/// Correct the terms at (x, y) (offset `i` into their error planes, `dx`
/// into their result rows) so that their rebuild equals `b` in each of the
/// `nc` channels: first within their noise, then what is left beyond it.
void reconcile_pixel(const float* b, const std::vector<SumTerm>& terms, int x, int y, int dx,
                     size_t i, int nc, RowShares& scratch)
{
    for (int c = 0; c < nc; ++c) {
        double rebuilt = 0.0;
        scratch.terms.clear();
        scratch.round.clear();
        for (size_t k = 0; k < terms.size(); ++k) {
            const SumTerm& t   = terms[k];
            float* value       = scratch.rows[k] + dx * t.result->nchannels() + c;
            const float colour = colour_at(t, x, y, c);
            rebuilt += double(colour) * double(*value);
            if (!(colour > 0.0f) || !std::isfinite(*value))
                continue;
            const float error = t.error->values[i];
            const Share share { value, colour, colour * colour * error, std::min(0.0f, *value),
                                HUGE_VALF };
            const float reach = share_reach * std::sqrt(error) / colour;
            // beyond the noise, shares by each term's part of the rebuild
            scratch.terms.push_back(share);
            scratch.terms.back().weight = 0.0f;
            scratch.round.push_back(share);
            scratch.round.back().low  = std::max(share.low, *value - reach);
            scratch.round.back().high = *value + reach;
        }
        const double rest = share_out(double(b[c]) - rebuilt, scratch.round);
        if (rest == 0.0)
            continue;
        scratch.round.assign(scratch.terms.begin(), scratch.terms.end());
        share_out(rest, scratch.round);
    }
}

}  // namespace

void reconcile_sum(const ImageBuf& beauty, const PixelBlock& raw,
                   const std::vector<SumTerm>& terms, int nthreads)
{
    if (terms.empty())
        return;
    const ROI roi = terms.front().result->roi();
    int nc        = std::min(raw.nchannels, colour_channels(beauty.nchannels()));
    for (const SumTerm& t : terms)
        nc = std::min({ nc, t.result->nchannels(), t.raw->nchannels,
                        t.colour ? t.colour->nchannels : nc });
    parallel_rows(roi, nthreads, [&](int y) {
        RowShares scratch;
        for (const SumTerm& t : terms)
            scratch.rows.push_back(static_cast<float*>(t.result->pixeladdr(roi.xbegin, y)));
        scratch.terms.reserve(terms.size());
        scratch.round.reserve(terms.size());
        const float* b = static_cast<const float*>(beauty.pixeladdr(roi.xbegin, y));
        size_t i       = pixel_offset(roi, roi.xbegin, y);
        for (int x = roi.xbegin; x < roi.xend; ++x, ++i)
            if (rebuilds(raw, terms, x, y, nc))
                reconcile_pixel(b + (x - roi.xbegin) * beauty.nchannels(), terms, x, y,
                                x - roi.xbegin, i, nc, scratch);
    });
}

}  // namespace mcdenoise
