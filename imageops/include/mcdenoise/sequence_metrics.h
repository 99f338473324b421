// sequence_metrics.h: quality metrics of a frame sequence against its
// per-frame references: per-frame relMSE, the temporal error (how wrong
// the frame-to-frame changes are) and, for a static shot, the flicker (how
// much a pixel boils across frames). Frames can be given all at once or
// fed one by one, so a long shot need not be held in memory.
#pragma once

#include <mcdenoise/export.h>
#include <mcdenoise/metrics.h>

#include <OpenImageIO/imagebuf.h>

#include <cstdint>
#include <string>
#include <vector>

MCDENOISE_API_BEGIN

using OIIO::ImageBuf;
using OIIO::ROI;

/// The figures of a sequence against its references.
struct SequenceComparison {
    std::vector<double> frame_rel_mse;  ///< relMSE of each frame, as `rel_mse` gives it
    double mean_rel_mse = 0;            ///< mean of `frame_rel_mse`
    double temporal_error = 0;          ///< see `compare_sequence`; NaN with fewer than 2 frames
    double flicker = 0;                 ///< see `compare_sequence`; NaN with fewer than 2 frames
    int frames = 0;                     ///< frames compared
    int64_t pixels = 0;                 ///< pixels finite in every frame (those the flicker covers)
    bool ok = false;                    ///< false if a frame could not be compared
    std::string error;                  ///< why, when `ok` is false
};

/// The running sums of a sequence comparison, fed frame by frame with
/// `add_sequence_frame` and read with `sequence_comparison`. Its members
/// are the state of those two functions: do not set them.
struct SequenceSums {
    ROI roi;                                 ///< settled on the first frame
    int nthreads = 0;
    SequenceComparison figures;              ///< per-frame relMSE so far, ok / error
    std::vector<float> previous_result;      ///< the last frame's ROI pixels
    std::vector<float> previous_reference;
    std::vector<uint8_t> finite;             ///< 1 where every frame so far was finite
    std::vector<double> result_mean;         ///< running mean of each value (Welford)
    std::vector<double> result_m2;           ///< running sum of squared deviations (Welford)
    std::vector<double> reference_sum;       ///< sum of each reference value over the frames
    double pair_rel_mse_sum = 0;             ///< sum over frame pairs of their difference relMSE
};

/// Compare `results[t]` with `references[t]` for every frame t of a shot,
/// in order, over `roi`.
///
/// The ROI is settled on the first frame as in `compare_images` (default:
/// the first result's data window and its first 3 channels) and is the
/// same for every frame; every image must cover it. Figures, with
/// epsilon = `rel_mse_epsilon` (0.01), x_t the result and r_t the reference
/// of frame t, over the ROI's values (pixels times channels):
///
/// - `frame_rel_mse[t]` = `rel_mse(x_t, r_t)`, and `mean_rel_mse` their mean;
/// - `temporal_error`: the relMSE of the frame-to-frame differences
///   against the references' differences, mean over the pairs of
///   successive frames (t-1, t) of the mean over values of
///   ((x_t - x_{t-1}) - (r_t - r_{t-1}))^2 / ((r_t - r_{t-1})^2 + epsilon),
///   over the pixels finite in all four images. It is 0 when the result
///   changes exactly as the references do; it measures boiling and
///   popping, where per-frame relMSE cannot tell a steady error from one
///   that changes every frame. The differences are taken in place (not
///   carried by motion): on a moving shot both sides move alike;
/// - `flicker` (meaningful for a static shot): the mean over values of
///   the variance of x_t across the frames (population variance, divided
///   by the frame count) over (mean_t r_t)^2 + epsilon, over the pixels
///   finite in every frame.
///
/// `results` and `references` must have the same, non-zero length; with
/// one frame, `temporal_error` and `flicker` are NaN. On any error `ok` is
/// false and `error` names the frame. Nothing throws and nothing prints.
/// Results are bit-identical for any `nthreads`.
SequenceComparison compare_sequence(const std::vector<const ImageBuf*>& results,
                                    const std::vector<const ImageBuf*>& references, ROI roi = {},
                                    int nthreads = 0);

/// The temporal error of `compare_sequence`; NaN if it cannot be computed.
double temporal_error(const std::vector<const ImageBuf*>& results,
                      const std::vector<const ImageBuf*>& references, ROI roi = {}, int nthreads = 0);

/// The flicker of `compare_sequence`; NaN if it cannot be computed.
double flicker(const std::vector<const ImageBuf*>& results, const std::vector<const ImageBuf*>& references,
               ROI roi = {}, int nthreads = 0);

/// Start a frame-by-frame comparison over `roi` (settled on the first
/// frame as in `compare_sequence`) on `nthreads` threads.
SequenceSums start_sequence(ROI roi = {}, int nthreads = 0);

/// Add the next frame of the shot (`result` against `reference`) to
/// `sums`; false if it cannot be compared (then `sums` stays failed and
/// `sequence_comparison` says why). Feeding every frame in order gives
/// exactly the figures of `compare_sequence`, holding only one frame's
/// pixels and the per-value running sums.
bool add_sequence_frame(SequenceSums& sums, const ImageBuf& result, const ImageBuf& reference);

/// The figures of the frames added to `sums` so far.
SequenceComparison sequence_comparison(const SequenceSums& sums);

MCDENOISE_API_END
