// layer_sums.h: light layers made to add up to the denoised beauty again
// after each was denoised as far as its own noise allows (layer_backoff.h):
// where the raw layers rebuild the raw beauty, the difference between the
// denoised beauty and the rebuild of the denoised layers is shared among
// the layers in proportion to their estimated error, within their noise
// first, never pushing one below zero.
#pragma once

#include "core/pixel_block.h"
#include "core/plane.h"

#include <OpenImageIO/imagebuf.h>

#include <vector>

namespace mcdenoise {

/// One term of a rebuild of the beauty: a layer, times its colour pass
/// when it has one.
struct SumTerm {
    OIIO::ImageBuf* result;        ///< the denoised layer, float with local pixels, corrected in place
    const PixelBlock* raw;         ///< the layer as rendered, over the result's ROI or more
    const PixelBlock* colour;      ///< its colour pass over the same, or nullptr (1)
    const Plane<float>* error;     ///< the result's estimated error variance, over its ROI
};

/// The most a raw rebuild may differ from the raw beauty, as a share of
/// |beauty| + the sum of |term|, for a pixel to count as rebuilt (half
/// floats round each value by up to 2^-11 of it).
constexpr float pixel_rebuild_tolerance = 1e-3f;

/// How far the difference may move a term in the first round, in
/// standard deviations of its estimated error: a move within its own noise.
constexpr float share_reach = 2.0f;

/// Correct the results of `terms` so that, per pixel of their ROI and
/// colour channel (the first three, or fewer), sum colour x result equals
/// `beauty` (the denoised beauty's colour, a float image over that ROI or
/// more) wherever sum colour x raw is within `pixel_rebuild_tolerance` of `raw`
/// (the raw beauty) in every colour channel. The difference goes to the
/// terms in proportion to colour^2 x error (where every error is 0, to
/// |colour x value|, each term's part of the rebuild; equal shares where
/// that is 0 too), each share divided by the term's colour; a term whose colour is
/// 0 takes none. First no term moves further than `share_reach` standard
/// deviations of its error (a move its own noise explains), nor below
/// min(0, its value), the rest going to the others. What they cannot take
/// within their noise is the beauty's own error more than theirs; it is
/// shared in proportion to each term's part of the rebuild, |colour x
/// value| (a gain on the rebuild), with min(0, value) the only bound.
/// What none can take stays (only where the beauty is below every term's
/// floor).
void reconcile_sum(const OIIO::ImageBuf& beauty, const PixelBlock& raw,
                   const std::vector<SumTerm>& terms, int nthreads);

}  // namespace mcdenoise
