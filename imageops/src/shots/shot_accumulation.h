// shot_accumulation.h: per-frame images of a shot (the network's results)
// averaged at each pixel of one frame with its neighbours' carried into its
// pixel grid, each neighbour weighed by how well it matches the frame there,
// judged on the noisy renders with the shot's own noise: what the network's
// cross-frame denoise writes.
#pragma once

#include "shots/temporal_frame.h"

#include <OpenImageIO/imagebuf.h>

#include <vector>

namespace mcdenoise {

/// Rows of the ROI accumulated at a time: the neighbours are carried into
/// one band at a time, so their planes stay small.
constexpr int accumulation_band_rows = 128;

/// Into `dst` (a float image over `roi`, every channel of `images[0]`): at
/// each pixel, `images[0]` (the centre frame's) averaged with each
/// neighbour's image `images[k + 1]` (the frame at `offsets[k]`) carried
/// into the centre's grid by the motion guides (Keys' cubic, kept within
/// the 2x2 pixels around the point, as the cross-frame denoise carries
/// values), the centre weighing 1 and a neighbour: 1 where it is in place
/// (not moved by the motion) and agrees with the centre (`shot_agreement`,
/// and its 3x3 patch within about three standard deviations of the noise
/// distance); elsewhere the temporal guide's weight at that pixel
/// (temporal_guide.h: its 3x3 patch's distance to the centre's, normalised
/// by the shot's noise, and its features); 0 where its motion carried to
/// the pixel is not the centre's (a pixel the motion uncovers or covers).
/// The matching reads the frames' prepared planes (the noisy renders), not
/// the images. Where no neighbour matches (a disocclusion, a moving object
/// or shadow) the result is the centre's image. Each image must have its frame's data
/// window. A channel not finite in a neighbour leaves it out there.
/// Returns false with `dst`'s error set on failure.
bool accumulate_shot(OIIO::ImageBuf& dst, const PreparedFrameData& centre,
                     const std::vector<const PreparedFrameData*>& neighbours,
                     const std::vector<int>& offsets,
                     const std::vector<const OIIO::ImageBuf*>& images, const OIIO::ROI& roi,
                     int nthreads);

}  // namespace mcdenoise
