// frame_warp.h: carrying a neighbour frame into the centre frame's pixel
// grid through the motion guides (vectors chained frame by frame, read at
// the nearest pixel), for the cross-frame denoise and its baseline.
#pragma once

#include <mcdenoise/temporal.h>

#include "core/plane.h"
#include "features/feature_field.h"

#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

namespace mcdenoise {

/// Where each pixel of a region of the centre frame lies in a neighbour
/// frame: the column and row of its source pixel (the nearest to where the
/// motion leads), or `no_source`, and how far from that pixel's centre the
/// motion leads (`dx`, `dy` in [-0.5, 0.5]).
struct WarpMap {
    Plane<int32_t> xs, ys;
    Plane<float> dx, dy;

    static constexpr int32_t no_source = std::numeric_limits<int32_t>::min();
    bool has_source(size_t i) const { return xs.values[i] != no_source; }
};

/// The map of `region` of the centre frame to the frame `offset` (non-zero)
/// frames away, whose data window is `source_dw`. `steps[k]` is the motion
/// (4 channels, Cycles' Vector convention, over `source_dw`) of the frame
/// k frames from the centre towards the neighbour, k < |offset|, or
/// nullptr where that frame's motion is unknown (the previous step's vector
/// stands in). Positions are chained in floats and each vector is read at
/// the nearest pixel; a pixel whose path leaves `source_dw` has no source.
/// With no motion for the centre (`steps[0]` null) every pixel is its own
/// source.
WarpMap motion_warp_map(const std::vector<const GuideChannels*>& steps, int offset,
                        const OIIO::ROI& region, const OIIO::ROI& source_dw, int nthreads);

/// The motion guide of every frame (the centre first, then `neighbours` in
/// order) over its data window; null for a frame without one. On failure
/// sets `dst`'s error prefixed with `op`.
bool load_motions(const char* op, OIIO::ImageBuf& dst, const FrameInput& centre,
                  const std::vector<FrameInput>& neighbours, int nthreads,
                  std::vector<std::unique_ptr<GuideChannels>>& motions);

/// The `steps` of `motion_warp_map` from the centre to the frame at
/// `offset`, from `motions` (the centre's, then those of the neighbours at
/// `offsets`, in order; null for a frame without one): null for a frame on
/// the way that is missing or has no motion.
std::vector<const GuideChannels*> motion_steps(const std::vector<const GuideChannels*>& motions,
                                               const std::vector<int>& offsets, int offset);

/// Every channel of `src` (and its finite mask) sampled where the motion
/// leads as `carry_frame` samples the values (Keys' cubic, bounded by the
/// 2x2 pixels around the point), 0 where there is no source.
Planes<float> warp_planes(const Planes<float>& src, const WarpMap& map, const OIIO::ROI& region,
                          int nthreads);

/// The regions of the centre frame a carried frame covers, each inside
/// `colour`.
struct CarryRegions {
    OIIO::ROI colour, variance, window;
};

/// A neighbour frame carried into the centre frame's pixel grid.
struct CarriedFrame {
    ColourPlanes colour;    ///< over the colour region (no luminance)
    ColourPlanes variance;  ///< over the variance region (no luminance)
    FeatureField features;  ///< over the colour region
    Planes<float> values;   ///< every channel and its finite mask, over the window
    Plane<float> usable;    ///< over the colour region: 1 where the pixel has a source, else 0
    /// Over the colour region: 1 where the carried colour is the source's
    /// within a fraction of its noise, else 0: the source is the same
    /// pixel, not moved (nothing resampled), or the bilinear sample's
    /// error, estimated from the second differences of the 4x4 source
    /// pixels around the point (exact for a quadratic), is at most half the
    /// standard deviation of the cell's pixels in every colour channel.
    Plane<float> faithful;
    Planes<float> excess;   ///< the frame's excess given out, over the window
};

/// Carry `src` (the planes of the frame `offset` frames from the centre,
/// each over that frame's data window `source_dw`) into the centre's
/// `regions`, through the map `motion_warp_map(steps, offset, ...)` gives,
/// in one pass: the colour sampled bilinearly where the motion leads (the
/// taps inside `source_dw`, their weights normalised), the variance as
/// that of the sample (the taps' values times their squared weights); the
/// values and finite masks with Keys' cubic (Catmull-Rom, a = -0.5, 4x4
/// taps, normalised the same way), kept within the values of the 2x2
/// pixels around the point: sharper than bilinear, without overshoot; the
/// features and ids from the nearest source pixel; 0 (ids: an id equal to
/// no other) where there is no source. The patches are compared on the
/// smoother bilinear colour (less noise, better matches); what is averaged
/// keeps the detail bilinear sampling blurs. `excess` (planes over
/// `source_dw`: the frame's outliers' excess as its own `denoise` gives it
/// out) is sampled bilinearly, as the colour (a spread-out excess needs no
/// sharper kernel).
CarriedFrame carry_frame(const FeatureInputs& src, const Planes<float>& excess,
                         const OIIO::ROI& source_dw,
                         const std::vector<const GuideChannels*>& steps, int offset,
                         const CarryRegions& regions, int nthreads);

}  // namespace mcdenoise
