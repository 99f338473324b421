// layer_backoff.h: a light layer after the beauty's weights averaged it,
// backed off per pixel towards its own values where the average moved it
// further than the layer's own noise explains (a direct pass's shadow edge
// blurred by weights that the indirect light's noise set), and the error
// variance that leaves, which says where the layers' rebuild may be
// corrected (layer_sums.h).
#pragma once

#include "core/pixel_block.h"
#include "core/plane.h"

#include <OpenImageIO/imagebuf.h>

namespace mcdenoise {

/// How far beyond the ROI the back-off reads the average and the layer:
/// a 3x3 window of 3x3 windows.
constexpr int backoff_reach = 2;

/// How far a pixel's relative noise (noise variance / squared level) may
/// exceed the layer's median relative noise before the window estimate is
/// taken for structure instead (a window across an edge of a pass with
/// little noise, as the sky seen through a window frame in Env).
constexpr float relative_noise_spread = 9.0f;

/// The median relative noise is taken over every `median_stride`-th pixel
/// in x and y: a sample of 1 in 16 is plenty for a median and spares the
/// selection over every pixel.
constexpr int median_stride = 4;

/// The planes `back_off_layer` works in, over the ROI: kept from one layer
/// to the next, so that each layer does not allocate them (and the system
/// clear their pages) afresh.
struct BackoffPlanes {
    Plane<float> noise;        ///< s2 from the windows alone, summed over channels
    Plane<float> residual;     ///< the same estimate of the average's own values
    Plane<float> mean_square;  ///< m2
    Plane<float> level;        ///< |average|^2
};

/// Back the average of one layer off towards its kept values, over the
/// pixels of `result` (float, the layer's channels, holding the average
/// over its ROI; changed in place). `planes` is working space, reused
/// from one call to the next.
///
/// `average` and `layer` hold the average and the layer's own values over
/// the ROI grown by `backoff_reach` and clipped to the data window; the
/// kept values are the layer's times `scale` (the outlier split's, over a
/// region holding that one), so fireflies stay out. Per pixel, with e =
/// average - kept (0 where not finite):
/// - m2, the 3x3 mean of |e|^2 (summed over channels): the average's bias
///   squared plus the layer's noise;
/// - s2, the layer's noise: per channel the smallest 3x3 sample variance
///   of e among the 3x3 windows around the pixel, summed, divided by
///   `smallest_window_bias`; at most `relative_noise_spread` times the
///   median over the ROI (every `median_stride`-th pixel) of that
///   estimate over the average's squared level |average|^2, times the
///   pixel's |average|^2 (where every window crosses an edge, the window
///   estimate measures the edge);
/// - a = clamp(1 - s2 / m2, 0, 1) (0 where m2 is 0), the blend that
///   minimises the squared error of average + a (kept - average) when
///   the average's bias is sqrt(m2 - s2) and the kept values' noise s2.
/// The result is average - a e. `error` (a plane over the ROI) gets its
/// estimated error variance, a^2 s2 + (1 - a)^2 (max(0, m2 - s2) + t2),
/// where t2, the noise left in the average, is the same estimate as s2 of
/// the average's own values, at most s2.
void back_off_layer(OIIO::ImageBuf& result, const PixelBlock& average, const PixelBlock& layer,
                    const Plane<float>& scale, int nthreads, BackoffPlanes& planes,
                    Plane<float>& error);

}  // namespace mcdenoise
