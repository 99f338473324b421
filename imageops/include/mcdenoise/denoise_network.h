// denoise_network.h: the trained denoiser: Intel Open Image Denoise 2.x's
// published networks (its weights, Apache-2.0) run by mcdenoise's own
// inference engine on oneDNN, with OIDN's whole pipeline for HDR renders.
#pragma once

#include <mcdenoise/export.h>
#include <mcdenoise/features.h>
#include <mcdenoise/temporal.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

MCDENOISE_API_BEGIN

/// Which of OIDN's networks run: OIDN's quality levels, the same files it
/// picks for each.
enum class NetworkQuality {
    fast,      ///< the `_small` networks where OIDN has one
    balanced,  ///< the default-size networks
    high,      ///< the `_large` networks where OIDN has one (OIDN's default)
};

/// How `denoise_network` runs, beyond the images.
struct NetworkOptions {
    NetworkQuality quality = NetworkQuality::high;
    /// Denoise the albedo and normal guides first, each by its own network
    /// (OIDN's `cleanAux`, Blender's "Accurate" prefilter), then the beauty
    /// with the network trained on clean guides. Off: the guides are taken
    /// as they are, by the network trained on noisy ones.
    bool prefilter_guides = true;
    /// The working memory the networks may take, in bytes: the images are
    /// cut into overlapping tiles small enough (never below 768 pixels a
    /// side, as OIDN). 0: OIDN's default, tiles of at most 2160 x 2160
    /// pixels. Tiled output equals whole-image output within float rounding.
    uint64_t memory_limit = 0;
    /// The folder of OIDN 2.x weight files (`rt_*.tza`). Empty: the
    /// environment's `MCD_WEIGHTS_DIR`, else the weights installed with the
    /// library, else those of its build tree.
    std::string weights_dir;
    /// Called as each phase ends ("read weights", "prefilter albedo",
    /// "prefilter normal", "autoexposure", "network") with its seconds.
    std::function<void(const std::string& phase, double seconds)> on_phase;
    /// Called after each tile of each network with the fraction of all the
    /// run's tiles done, from 0 to 1.
    std::function<void(double fraction)> on_progress;
};

/// Denoise the colour of a Monte Carlo render (channels 0-2, linear HDR)
/// with OIDN's networks; further channels (alpha) are copied unchanged.
///
/// OIDN's RT pipeline, step by step as OIDN 2.4 runs it (docs/network.md):
/// the exposure is measured over the whole ROI (the key 0.18 over the
/// geometric mean of 16 x 16-pixel bin luminances); the colour is scaled by
/// it, sanitised (NaN to 0, clamped to [0, FLT_MAX]) and put through the
/// PU transfer; the albedo (3 channels; 1 is taken as grey) is clamped to
/// [0, 1] and the normal (3 channels, any length, any space) to [-1, 1];
/// with `prefilter_guides`, both are denoised by `rt_alb*` and `rt_nrm*`
/// first; the image is padded to multiples of 16 and, beyond the memory
/// limit, tiled with an overlap of the receptive field; the output is
/// decoded and scaled back. Weights by guides present: albedo and normal
/// `rt_hdr_calb_cnrm` (prefiltered) or `rt_hdr_alb_nrm`; albedo alone
/// `rt_hdr_alb`; none `rt_hdr`. A normal without an albedo is not read
/// (OIDN has no network for it). Other guides are not read.
///
/// The `dst` attribute `mcdenoise:denoise_guides` lists the guides read,
/// `mcdenoise:network` the weight files run.
///
/// @param beauty   The noisy render: at least 3 channels, colour first.
/// @param guides   `albedo` and `normal`, if present, covering the ROI.
/// @param options  Quality, prefiltering, memory, weights, callbacks.
/// @param roi      Must include channels 0-2.
ImageBuf denoise_network(const ImageBuf& beauty, const Guides& guides = {},
                         const NetworkOptions& options = {}, ROI roi = {}, int nthreads = 0);
/// Write to an existing image `dst` (allocating if it is uninitialized).
bool denoise_network(ImageBuf& dst, const ImageBuf& beauty, const Guides& guides = {},
                     const NetworkOptions& options = {}, ROI roi = {}, int nthreads = 0);

/// One frame of a shot ready for the network's cross-frame denoise: the
/// frame prepared as for the cross-frame `denoise` (temporal.h) and its
/// network result alone. A sequence makes each frame's once and passes it
/// to every window it is in, as the centre and as a neighbour. Copies
/// share the planes and the result, which never change.
struct NetworkFrame {
    PreparedFrame prepared;
    /// `denoise_network` of the frame over its data window; null unless
    /// made successfully.
    std::shared_ptr<const ImageBuf> denoised;
    /// Why making it failed; empty if it succeeded or was not attempted.
    std::string error;
};

/// Make `frame`'s `NetworkFrame`: `prepare_frame`, then `denoise_network`
/// of its beauty with its albedo and normal over its data window, as
/// `options` say. On failure the result has no `denoised` and an `error`.
NetworkFrame prepare_network_frame(const FrameInput& frame, const NetworkOptions& options = {},
                                   int nthreads = 0);

/// Denoise one frame of a shot with the network, so the shot does not
/// flicker: each frame's network result (`NetworkFrame::denoised`)
/// averaged across the frames that show the same thing.
///
/// 1. Each frame alone: prepared as for the cross-frame `denoise` (its
///    noise, features and motion) and denoised by the network
///    (`prepare_network_frame`).
/// 2. Each neighbour is carried into the centre's pixel grid by the motion
///    guides and matched with the centre as the cross-frame `denoise`
///    matches it (steps 2 to 4 there), on the noisy renders: the shot's
///    own noise, then the temporal guide's weight of the neighbour at each
///    pixel (its 3x3 patch against the centre's, normalised by that noise,
///    and its features).
/// 3. A neighbour's weight is 1 where it is in place (not moved by the
///    motion) and agrees with the centre (its features match, its 7x7 mean
///    within the noise of the centre's, and its 3x3 patch within about
///    three standard deviations of the noise distance); elsewhere the
///    temporal guide's weight; 0 where its motion, carried to the centre's
///    pixel, differs from the centre's by more than half a pixel plus a
///    tenth of the centre's (a pixel the motion uncovers or covers).
/// 4. At each pixel the centre's network result averaged with each
///    neighbour's result carried there (Keys' cubic, kept within the 2x2
///    pixels around the point), the centre weighing 1, a neighbour its
///    weight. Where nothing matches (a disocclusion, a moving object or
///    shadow) it is the centre's own result.
///
/// With no neighbours the result is the centre's network result over the
/// ROI, bit for bit. Every frame must have the centre's data window,
/// channel count and guides (the cross-frame `denoise`'s checks and
/// messages); an unprepared frame, or one whose preparation failed, is an
/// error naming it. The attribute `mcdenoise:denoise_frames` is the count
/// of frames used.
ImageBuf denoise_network(const NetworkFrame& centre, const std::vector<NetworkFrame>& neighbours,
                         const std::vector<int>& offsets, ROI roi = {}, int nthreads = 0);
/// Write to an existing image `dst` (allocating if it is uninitialized).
bool denoise_network(ImageBuf& dst, const NetworkFrame& centre,
                     const std::vector<NetworkFrame>& neighbours, const std::vector<int>& offsets,
                     ROI roi = {}, int nthreads = 0);
/// The same, of frames not yet prepared (each is made once with
/// `prepare_network_frame`).
ImageBuf denoise_network(const FrameInput& centre, const std::vector<FrameInput>& neighbours,
                         const std::vector<int>& offsets, const NetworkOptions& options = {},
                         ROI roi = {}, int nthreads = 0);
/// Write to an existing image `dst` (allocating if it is uninitialized).
bool denoise_network(ImageBuf& dst, const FrameInput& centre,
                     const std::vector<FrameInput>& neighbours, const std::vector<int>& offsets,
                     const NetworkOptions& options = {}, ROI roi = {}, int nthreads = 0);

/// Each quality and its name ("fast", "balanced", "high"): the one table
/// of quality names that mcdtool's modifier and Python's `quality` read.
struct NetworkQualityName {
    NetworkQuality quality;
    const char* name;
};
inline constexpr NetworkQualityName network_quality_names[] = {
    { NetworkQuality::fast, "fast" },
    { NetworkQuality::balanced, "balanced" },
    { NetworkQuality::high, "high" },
};

/// The guides `denoise_network` reads.
constexpr GuideMask denoise_network_guides = guide_bit("normal") | guide_bit("albedo");

MCDENOISE_API_END
