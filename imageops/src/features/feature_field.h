// feature_field.h: what the feature-guided filters (cross_bilateral, atrous,
// nlmeans) share: checking their guides, the feature weight of
// features.h as scaled feature planes and an id plane, the colour and
// luminance of a pixel as the weights see it, and the per-pixel variance.
#pragma once

#include <mcdenoise/features.h>

#include "core/guides.h"
#include "core/pixel_block.h"
#include "features/weighted_sums.h"

#include <array>

namespace mcdenoise {

/// Check that `guide` (named `name`) is readable, has three channels or one,
/// and covers `roi`; else set `dst`'s error prefixed with `op`, return false.
bool check_colour_guide(const char* op, const char* name, OIIO::ImageBuf& dst,
                        const OIIO::ImageBuf& guide, const OIIO::ROI& roi);

/// Check every guide in `guides` a feature-guided filter reads (all but the
/// halves) against `roi`.
bool check_feature_guides(const char* op, OIIO::ImageBuf& dst, const Guides& guides,
                          const OIIO::ROI& roi);

/// Channel planes of a guide over a region: non-finite values and pixels
/// outside the guide's data window as 0.
using GuideChannels = Planes<float>;

/// Read every channel of `guide` over `region` as `GuideChannels`.
bool load_guide_channels(const char* op, OIIO::ImageBuf& dst, const OIIO::ImageBuf& guide,
                         const OIIO::ROI& region, int nthreads, GuideChannels& out);

/// The feature weight of features.h over a region: each present feature
/// dimension as a plane of values scaled so that the exponent
/// `(A + N + Z) / 2` is the squared distance of the feature vectors, plus
/// the object ids when given.
struct FeatureField {
    Planes<float> dims;
    /// Object ids (as `load_object_ids` gives them) over the dims' region;
    /// no values without an object id guide.
    IdPlane ids;

    /// The weights of center (x0 + i, y) and neighbour (x0 + i + dx, y + dy)
    /// for i < n: `w[i] = scale * exp(-(e[i] + (A + N + Z) / 2))`, where
    /// `e` holds the filter's own exponent, 0 past `max_weight_exponent`
    /// and 0 across object ids. Both pixels must lie in the dims' region.
    void weights_row(int y, int x0, int n, int dx, int dy, const float* e, float scale,
                     float* w) const;
    /// `weights_row` with the neighbour's features read from `other` (the
    /// same dimensions, in the same pixel grid, over a region holding the
    /// neighbours: another frame carried into this one's grid).
    void weights_row(int y, int x0, int n, int dx, int dy, const float* e, float scale,
                     float* w, const FeatureField& other) const;
};

/// Read the features of `guides` (checked with `check_feature_guides`) over
/// `region`, scaled by `sigmas`.
bool load_feature_field(const char* op, OIIO::ImageBuf& dst, const Guides& guides,
                        const FeatureSigmas& sigmas, const OIIO::ROI& region, int nthreads,
                        FeatureField& field);

/// Colour channel planes and a luminance plane over one region.
struct ColourPlanes {
    Planes<float> colour;
    Plane<float> luminance;

    int nchannels() const { return colour.nchannels(); }
    const OIIO::ROI& region() const { return luminance.region; }
};

/// The colour of features.h (the first three channels, non-finite as 0)
/// and its luminance over a region.
using ColourField = ColourPlanes;

/// The luminance weights of features.h for `nc` colour channels.
std::array<float, feature_colour_channels> luminance_weights(int nc);

/// The colour count of a beauty with `nchannels` channels.
inline int colour_channels(int nchannels)
{
    return nchannels < feature_colour_channels ? nchannels : feature_colour_channels;
}

/// The colour field of `block` (whose channels start at 0) over `region`
/// (inside the block).
ColourField colour_field(const PixelBlock& block, const OIIO::ROI& region, int nthreads);

/// Per-pixel variance of the colour channels and of the luminance.
using VarianceField = ColourPlanes;

/// The variance of features.h over `region`: from `variance` when given
/// (checked with `check_feature_guides`), else estimated from `colour`,
/// which must cover `region` grown by one pixel (clipped to `data_window`).
bool load_variance(const char* op, OIIO::ImageBuf& dst, const OIIO::ImageBuf* variance,
                   const ColourField& colour, const OIIO::ROI& region,
                   const OIIO::ROI& data_window, int nthreads, VarianceField& out);

/// Everything a variance-guided filter (atrous, nlmeans) reads, each
/// converted once.
struct FeatureInputs {
    FeatureField features;   ///< over the window region
    ColourField colour;      ///< over the variance region grown by 1
    VarianceField variance;  ///< over the variance region
    SumSource values;        ///< every beauty channel, over the window region
};

/// Read `beauty` and `guides` (checked with `check_feature_guides`): the
/// features and values over `window`, the colour and variance over
/// `variance_region` (both inside the beauty's data window).
bool load_feature_inputs(const char* op, OIIO::ImageBuf& dst, const OIIO::ImageBuf& beauty,
                         const Guides& guides, const FeatureSigmas& sigmas,
                         const OIIO::ROI& window, const OIIO::ROI& variance_region,
                         int nthreads, FeatureInputs& in);

}  // namespace mcdenoise
