// shot_variance.h: the noise a shot measures of itself: the spread of a
// pixel's colour across the frames that show the same thing there, free of
// the spatial structure a single frame's estimate counts as noise.
#pragma once

#include "features/nlmeans_frames.h"

#include <vector>

namespace mcdenoise {

/// Radius of the box in which a neighbour's mean colour must agree with
/// the centre's for its pixel to count in the spread.
constexpr int agreement_radius = 3;

/// Each frame's variance (`frames[k].variance`) over `region`, raised at
/// each pixel to the sample variance of the colours of the frames that
/// agree with the centre (`frames[0]`) there, when three or more do. A
/// neighbour agrees where it was carried faithfully (`faithful`: in place,
/// or resampled with an error well within its noise), its features match
/// the centre's (feature weight, as features.h weighs them,
/// at least 1/4) and its mean colour over the
/// (2 agreement_radius + 1)^2 box (clipped to `dw`) is within
/// `agreement_sigmas` standard deviations of the centre's, the variance of
/// the difference of the two means taken as twice the centre's mean
/// variance over the box times `correlated_pixels` over the box's pixel
/// count (a renderer's pixel filter correlates neighbouring pixels). So a
/// moving shadow or object, which disagrees over the whole box, is left
/// out, while a cluster of rare bright samples the pixel filter spread
/// over a few pixels counts. Every frame's colour and
/// features must cover `region` grown by `agreement_radius` (clipped to
/// `dw`), the centre's variance too; `faithful[k]` (1 where frame k + 1 was
/// carried faithfully, `CarriedFrame::faithful`) the region. Where nothing
/// can agree (fewer than three frames, or no neighbour carried faithfully
/// anywhere in the planes) the result is empty: the frames' own variances
/// stand.
std::vector<VarianceField> shot_variance(const std::vector<NlmFrame>& frames,
                                         const std::vector<const Plane<float>*>& faithful,
                                         const OIIO::ROI& region, const OIIO::ROI& dw,
                                         int nthreads);

/// Whether each neighbour (`frames[k]`, k >= 1) agrees with the centre at
/// each pixel of `region` as `shot_variance` decides it (1 or 0): carried
/// faithfully, its features matching and its box mean within the noise of
/// the centre's. The inputs as for `shot_variance`; one plane per
/// neighbour over `region`.
std::vector<Plane<float>> shot_agreement(const std::vector<NlmFrame>& frames,
                                         const std::vector<const Plane<float>*>& faithful,
                                         const OIIO::ROI& region, const OIIO::ROI& dw,
                                         int nthreads);

}  // namespace mcdenoise
