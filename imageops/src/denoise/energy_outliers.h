// energy_outliers.h: `denoise`'s outlier step, which keeps energy: the part
// of a pixel above `clamp_fireflies`' bound is taken out of the beauty
// before anything is averaged and given back afterwards. A known firefly
// (its measured noise says so) is spread wide, by a normalised Gaussian; an
// outlier no noise measure judged goes back over the pixels its own
// NL-means window says are alike to it, so a glint, alike to nothing
// around it, keeps its light where it is.
#pragma once

#include <mcdenoise/features.h>

#include "core/pixel_block.h"
#include "core/plane.h"
#include "features/feature_field.h"
#include "features/firefly_scales.h"
#include "features/nlmeans_frames.h"
#include "features/weighted_sums.h"

#include <OpenImageIO/imagebuf.h>

#include <vector>

namespace mcdenoise {

/// Standard deviation, in pixels, of the Gaussian a known firefly's excess
/// is spread with.
constexpr float excess_spread_sigma = 10.0f;
/// Radius of that Gaussian (3 sigma): the excess of a pixel reaches this far.
constexpr int excess_spread_radius = 30;
/// A pixel above the firefly bound is kept whole when its excess exceeds
/// this many standard deviations of its measured noise: a highlight the
/// samples agree on, not a firefly.
constexpr float consistent_excess_sigmas = 2.0f;
/// What the split did to each pixel, to do the same to further layers.
struct SplitScales {
    /// The factor the kept colour is of the input's: the clamp's, or 1
    /// where a highlight is kept whole.
    Plane<float> scale;
    /// 1 where the part taken is excess to give back, else 0.
    Plane<uint8_t> gives_back;
};

/// Split `beauty` over `region` (inside its data window, all channels) into
/// `kept`, `clamp_fireflies(beauty, factor, radius)`, except where the
/// luminance excess over the bound exceeds `consistent_excess_sigmas`
/// standard deviations of the pixel's measured noise (`variance`, a
/// variance guide as features.h reads it; without it every clamped pixel
/// gives back), and `excess = beauty - kept`, one plane per channel of
/// `beauty` over `region` (0 for the channels beyond the colour, such as
/// alpha, and where a value is not finite). With `scales`, what was done
/// to each pixel of `region` goes there too, to split further layers alike
/// (`split_layer`). On failure sets `dst`'s error prefixed with `op`.
bool split_outliers(const char* op, OIIO::ImageBuf& dst, const OIIO::ImageBuf& beauty,
                    const OIIO::ImageBuf* variance, float factor, int radius,
                    const OIIO::ROI& region, int nthreads, OIIO::ImageBuf& kept,
                    Planes<float>& excess, SplitScales* scales = nullptr);

/// The split of `scales` applied to a layer `in` (every channel, over the
/// scales' region): `kept` the layer times each pixel's scale (non-finite
/// values as they are) over `values_region` (inside that region) as a
/// `SumSource`, and `excess` = in - kept where the pixel gives back and the
/// value is finite, else 0, over the scales' region.
void split_layer(const PixelBlock& in, const SplitScales& scales, const OIIO::ROI& values_region,
                 int nthreads, SumSource& kept, Planes<float>& excess);

/// Where the excess goes. `wide`: every pixel's excess spread by the
/// Gaussian of `excess_spread_sigma` normalised per source pixel over
/// `data_window` (the known fireflies of a measured noise). Else over each
/// source's NL-means window: the weights of every pixel that holds excess,
/// normalised to sum 1, so its excess is given out whole among the pixels
/// alike to it.
struct ExcessWeights {
    bool wide = false;
    OIIO::ROI data_window;
    int radius = 0;
    /// The pixels holding excess, row by row (x ascending within a row).
    std::vector<PixelXY> sources;
    /// (2 radius + 1)^2 weights per source, by `window_weights`' layout.
    std::vector<float> weights;
};

/// The weights of one source's window in `weights`: (2 radius + 1)^2.
inline size_t window_size(const ExcessWeights& weights)
{
    return size_t(2 * weights.radius + 1) * size_t(2 * weights.radius + 1);
}

/// The sources of `excess`: the pixels of `sources` (inside `excess`'s
/// region) where any plane is not 0, with windows of `radius` and every
/// weight 0, to be filled (`weight_tap`, `fill_outside`) and then
/// normalised (`normalise_weights`).
ExcessWeights excess_sources(const Planes<float>& excess, const OIIO::ROI& sources, int radius);

/// The tap through which `nlmeans_frames`, filtering `roi` with the own
/// window of radius `weights.radius`, fills the weights of the sources
/// inside `roi` (`weights` must outlive it).
WeightTap weight_tap(ExcessWeights& weights, const OIIO::ROI& roi);

/// Whether any source of `weights` lies outside `roi`.
bool sources_outside(const ExcessWeights& weights, const OIIO::ROI& roi);

/// Fill the weights of the sources outside `roi` with `window_weights` of
/// `frame` (its search radius `weights.radius`) compared with `colour`,
/// `variance`, `dw`, `patch_radius` and `strength`: the weights the
/// average would have given them.
void fill_outside(ExcessWeights& weights, const OIIO::ROI& roi, const NlmFrame& frame,
                  const ColourField& colour, const VarianceField& variance,
                  const OIIO::ROI& dw, int patch_radius, float strength, int nthreads);

/// Scale each source's weights to sum 1 (its own weight, 1, keeps the sum
/// above 0).
void normalise_weights(ExcessWeights& weights);

/// The excess given out over `roi`: a float image over `roi` with
/// `nchannels` channels, channel c (for each plane c of `excess`) holding,
/// when `weights.wide`, `sum_q excess_c(q) g(p - q) / n(q)` (g: the Gaussian
/// of `excess_spread_sigma`; n(q): the sum of g over the pixels of the data
/// window; `excess` must cover `roi` grown by `excess_spread_radius`,
/// clipped to it), else `sum_q excess_c(q) w_q(p - q)` over the sources q of
/// `weights` (`excess` must cover every source); the other channels 0.
OIIO::ImageBuf spread_excess(const ExcessWeights& weights, const Planes<float>& excess,
                             const OIIO::ROI& roi, int nchannels, int nthreads);

/// `spread_excess` over `roi` as planes, one per plane of `excess`.
Planes<float> spread_excess_planes(const ExcessWeights& weights, const Planes<float>& excess,
                                   const OIIO::ROI& roi, int nthreads);

/// The alpha channel `give_back_excess` keeps the colour of `beauty` under:
/// its `spec().alpha_channel` when set, else channel 3 when the beauty has
/// channels beyond the colour, else -1.
int premultiplied_alpha(const OIIO::ImageBuf& beauty);

/// Add the excess given out (`spread_excess`) to `dst` over `roi`, one
/// factor per pixel for every channel, so what is linear across channels
/// stays so. With an alpha channel (`alpha_channel` >= 0) the factor is
/// lowered, at the pixels where the excess would lift a colour channel
/// above alpha, to what keeps it at alpha (premultiplied colour stays <=
/// alpha where it was). With `factors`, each pixel's factor over `roi` goes
/// there too. On failure sets `dst`'s error prefixed with `op`.
bool give_back_excess(const char* op, OIIO::ImageBuf& dst, const ExcessWeights& weights,
                      const Planes<float>& excess, const OIIO::ROI& roi, int alpha_channel,
                      int nthreads, Plane<float>* factors = nullptr);

/// `give_back_excess` of an excess already given out: `spread`, a float
/// image with `dst`'s channels covering `roi`.
bool give_back_spread(const char* op, OIIO::ImageBuf& dst, const OIIO::ImageBuf& spread,
                      const OIIO::ROI& roi, int alpha_channel, int nthreads,
                      Plane<float>* factors = nullptr);

/// Add a layer's excess given out (`spread_excess`) times `factors` (the
/// beauty's, from `give_back_excess`) to `dst`, a float image with local
/// pixels and a channel per excess plane, over `roi`.
void give_back_layer_excess(OIIO::ImageBuf& dst, const ExcessWeights& weights,
                            const Planes<float>& excess, const OIIO::ROI& roi,
                            const Plane<float>& factors, int nthreads);

}  // namespace mcdenoise
