// features.h: the auxiliary buffers the feature-guided filters read
// (`Guides`) and how strongly each feature difference lowers a neighbour's
// weight (`FeatureSigmas`), shared by cross_bilateral.h, atrous.h and
// nlmeans.h.
#pragma once

#include <mcdenoise/export.h>
#include <mcdenoise/simple.h>

MCDENOISE_API_BEGIN

/// The auxiliary buffers a feature-guided filter may use. Any may be absent
/// (nullptr); each present one must cover the ROI (data windows) with the
/// channel counts of the guide roles table in docs/filters.md.
///
/// Windows may reach past the ROI into the rest of the beauty's data
/// window; a guide pixel outside the guide's own data window reads as "no
/// value": an id equal to no other (the neighbour is left out), no normal,
/// infinitely far, albedo 0, variance 0.
struct Guides {
    const ImageBuf* object_id = nullptr;  ///< 1 channel, compared as rounded integers, NaN = -1
    const ImageBuf* normal    = nullptr;  ///< 3 channels, any length
    const ImageBuf* depth     = nullptr;  ///< 1 channel
    const ImageBuf* albedo    = nullptr;  ///< 3 or 1 channels
    const ImageBuf* variance  = nullptr;  ///< 3 or 1 channels (variance of the pixel mean)
    const ImageBuf* half_a    = nullptr;  ///< like beauty (used by denoise only)
    const ImageBuf* half_b    = nullptr;  ///< like beauty (used by denoise only)
    /// 4 channels (used by the cross-frame denoise of temporal.h only):
    /// screen-space motion in pixels, Cycles' Vector convention: pixel
    /// (x, row) of this frame was at (x + X, row - Y) in the previous frame
    /// and is at (x - Z, row + W) in the next (rows counted downwards).
    const ImageBuf* motion = nullptr;
};

/// A set of `Guides` fields, one bit each: which guides an operation
/// reads.
using GuideMask = unsigned;

/// One field of `Guides`: the name that stands for it everywhere (the C++
/// field, Python's `guides` keys, the library's messages), its bit in a
/// `GuideMask` and the member itself.
struct GuideField {
    const char* name;
    GuideMask bit;
    const ImageBuf* Guides::*member;
};

/// Every field of `Guides`, in declaration order: the one table of guide
/// names that mcdtool's roles, the Python module and the tests derive theirs
/// from.
inline constexpr GuideField guide_fields[] = {
    { "object_id", 1u << 0, &Guides::object_id }, { "normal", 1u << 1, &Guides::normal },
    { "depth", 1u << 2, &Guides::depth },         { "albedo", 1u << 3, &Guides::albedo },
    { "variance", 1u << 4, &Guides::variance },   { "half_a", 1u << 5, &Guides::half_a },
    { "half_b", 1u << 6, &Guides::half_b },       { "motion", 1u << 7, &Guides::motion },
};

/// The bit of the field named `name` in `guide_fields`, 0 for no field.
constexpr GuideMask guide_bit(const char* name)
{
    for (const GuideField& field : guide_fields) {
        const char *a = field.name, *b = name;
        while (*a && *a == *b)
            ++a, ++b;
        if (*a == *b)
            return field.bit;
    }
    return 0;
}

/// The guides the feature weight reads when present (docs/filters.md).
constexpr GuideMask feature_weight_guides = guide_bit("object_id") | guide_bit("normal") | guide_bit("depth")
                                           | guide_bit("albedo");
/// The guides each feature-guided operation uses when present: every other
/// field of `Guides` is ignored.
constexpr GuideMask cross_bilateral_guides = feature_weight_guides;
constexpr GuideMask atrous_guides          = feature_weight_guides | guide_bit("variance");
constexpr GuideMask nlmeans_guides         = feature_weight_guides | guide_bit("variance");
constexpr GuideMask clamp_fireflies_guides = guide_bit("object_id");
/// `denoise` of one frame (denoise.h): no object id, the halves for the
/// variance.
constexpr GuideMask denoise_guides = guide_bit("normal") | guide_bit("depth") | guide_bit("albedo")
                                    | guide_bit("variance") | guide_bit("half_a") | guide_bit("half_b");
/// `denoise` across frames (temporal.h): the motion guide too.
constexpr GuideMask denoise_frames_guides = denoise_guides | guide_bit("motion");

/// How fast a neighbour's weight falls with each feature difference.
/// A sigma <= 0 (or an absent guide) leaves that feature out.
///
/// The feature weight of neighbour q for center p is
/// `wf = exp(-(A + N + Z) / 2)`, with
/// `A = |a_p - a_q|^2 / albedo^2` (non-finite albedo taken as 0),
/// `N = |n_p - n_q|^2 / normal^2` of the normalised normals (a zero-length
/// or non-finite normal is (0, 0, 0)) and
/// `Z = (l(d_p) - l(d_q))^2 / depth^2` with `l(d) = ln(d)` for finite
/// `0 < d < 1e9` and `ln(1e9)` otherwise ("infinitely far": non-finite,
/// >= 1e9 and <= 0, which is how Cycles and Tungsten mark escaped rays);
/// `wf = 0` when an object id is given and the rounded ids differ (SPEC's
/// object rule: a hard edge).
///
/// Every filter multiplies its weight factors as one exponential
/// `exp(-(sum of exponents))`, computed in float with a fast exp (relative
/// error below 2e-5); a total exponent of 87 or more (past float's
/// smallest normal number) gives weight 0.
struct FeatureSigmas {
    float albedo = 0.1f;  ///< albedo difference scale
    float normal = 0.3f;  ///< unit-normal difference scale
    float depth  = 0.1f;  ///< log-depth difference scale
};

/// The colour of a pixel, as the weights of the feature-guided filters see
/// it: the beauty's first three channels (all of them when it has fewer),
/// non-finite values taken as 0. Further channels (alpha) are filtered but
/// never compared. Its luminance is `0.2126 R + 0.7152 G + 0.0722 B` for
/// three colour channels, else the mean of the colour channels.
///
/// The variance the weights use is, per colour channel, `Guides::variance`
/// (a one-channel variance serves every channel; non-finite or negative
/// values are taken as 0) or, when absent, the sample variance (divided by
/// n - 1, 0 when n == 1) of the colour over the 3x3 window clipped to the
/// data window. The luminance variance is `sum_c lw_c^2 var_c` with the
/// luminance weights `lw` above, or when estimated, the sample variance of
/// the luminance over the same window.
constexpr int feature_colour_channels = 3;

MCDENOISE_API_END
