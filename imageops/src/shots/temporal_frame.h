// temporal_frame.h: what `prepare_frame` keeps of a frame of a shot for the
// cross-frame denoise (temporal.h), and the checks of one frame's inputs.
#pragma once

#include <mcdenoise/temporal.h>

#include "denoise/denoise_frame.h"
#include "features/feature_field.h"

#include <string>
#include <vector>

namespace mcdenoise {

/// A frame prepared over its data window: `denoise`'s first steps and the
/// planes the cross-frame average reads of it, as the centre or as a
/// neighbour. Not movable (`frame.guides` may point into `frame`).
struct PreparedFrameData {
    FrameInput input;     ///< the frame as given
    /// The clamped beauty and the strength (its variance image, guides and
    /// excess are dropped once read into `planes` and `given_excess`).
    DenoiseFrame frame;
    FeatureInputs planes; ///< features, colour, variance and values over the data window
    /// The outliers' excess over the data window as the frame's own
    /// `denoise` gives it out (a plane per channel).
    Planes<float> given_excess;
    GuideChannels motion; ///< the motion guide over the data window; no planes without one

    bool has_motion() const { return !motion.values.empty(); }
};

/// The operation name of the cross-frame denoise's messages.
constexpr const char* temporal_op = "denoise";

/// Check `frame` (called `what` in messages) as the cross-frame denoise
/// reads it over `roi`: a beauty, the guides `denoise` reads, a motion
/// guide of 4 channels. On failure sets `dst`'s error.
bool check_frame(OIIO::ImageBuf& dst, const FrameInput& frame, const std::string& what,
                 const OIIO::ROI& roi);

/// Check the neighbours of `centre` (the frames at `offsets`) as the
/// cross-frame denoise reads them: one offset each, non-zero and distinct;
/// each frame as `check_frame` checks it, with the centre's data window,
/// channel count and set of the guides `denoise` reads. On failure sets
/// `dst`'s error.
bool check_neighbours(OIIO::ImageBuf& dst, const FrameInput& centre,
                      const std::vector<FrameInput>& neighbours, const std::vector<int>& offsets);

/// The data of the prepared `centre` and `neighbours` (into `c` and `ns`),
/// checked with `check_neighbours`; an unprepared frame or one that failed
/// to prepare is an error naming it, set on `dst`.
bool shot_data(OIIO::ImageBuf& dst, const PreparedFrame& centre,
               const std::vector<PreparedFrame>& neighbours, const std::vector<int>& offsets,
               const PreparedFrameData*& c, std::vector<const PreparedFrameData*>& ns);

}  // namespace mcdenoise
