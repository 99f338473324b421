// shot.h: the animated testrender shots of the shot set (make_shot_set),
// the per-frame, baseline and cross-frame results on them, and the shot
// metrics, for the cross-frame quality tests and docs/temporal.md's table.
#pragma once

#include "support/render_file.h"

#include <mcdenoise/temporal.h>

#include <functional>
#include <string>
#include <vector>

namespace testimg {

/// Consecutive 16-spp frames of one shot, from frame `first` on.
struct Shot {
    std::vector<Render> frames;
    int first = 0;
    std::string error;  ///< set when a frame could not be read

    /// Frame `t` (a frame number) as the cross-frame denoise takes it, with
    /// every guide, the motion when `motion` is true.
    mcdenoise::FrameInput input(int t, bool motion) const;
    /// The frames within `n` of frame `t` that the shot holds, without t.
    std::vector<int> neighbours(int t, int n) const;
    int last() const { return first + int(frames.size()) - 1; }
};

/// The shot set's directory: $MCD_SHOTSET_DIR, else `fallback`.
std::string shotset_dir(const std::string& fallback);

/// Read frames `first`..`last` of `shot` (e.g. "shot_truck") from `dir`.
Shot read_shot(const std::string& dir, const std::string& shot, int first, int last);

/// The beauty of a reference (or other) render of the shot set.
OIIO::ImageBuf read_beauty(const std::string& path, std::string& error);

/// Every frame denoised alone (`denoise` with every guide).
std::vector<OIIO::ImageBuf> per_frame(const Shot& shot);

/// Frame `t` denoised with its neighbours within `n` frames.
OIIO::ImageBuf cross_frame(const Shot& shot, int t, int n, bool motion, int nthreads = 0);

/// The baseline of docs/temporal.md for frame `t`: the per-frame results
/// (`denoised[i]` for frame `first + i`) within `n` frames averaged where
/// the motion-carried depth agrees.
OIIO::ImageBuf baseline(const Shot& shot, const std::vector<OIIO::ImageBuf>& denoised, int t,
                        int n);

/// A one-channel mask over `like`'s data window: 1 where `keep(x, y)`.
OIIO::ImageBuf pixel_mask(const OIIO::ImageBuf& like, const std::function<bool(int, int)>& keep);

/// Pixels of frame `t` that a neighbour within one frame does not show:
/// the motion carries them out of the frame or onto another object id.
OIIO::ImageBuf disoccluded_pixels(const Shot& shot, int t);

/// Pixels of frame `t` showing the background (`object_id` != `object`)
/// where `others` (references of other frames) differ from `reference` by
/// more than 10 % of its value plus 0.01: where the object or its shadow
/// was in another frame.
OIIO::ImageBuf left_behind_pixels(const Shot& shot, int t, float object,
                                  const OIIO::ImageBuf& reference,
                                  const std::vector<OIIO::ImageBuf>& others);

}  // namespace testimg
