// temporal.cpp: the cross-frame denoise: the frames prepared
// (temporal_frame.h), the neighbours carried into the centre's pixel grid,
// the temporal guide, then one NL-means average over the centre's window
// and the neighbours' windows.
#include <mcdenoise/temporal.h>

#include "core/guides.h"
#include "core/operation.h"
#include "core/window.h"
#include "denoise/denoise_frame.h"
#include "denoise/energy_outliers.h"
#include "features/feature_field.h"
#include "features/nlmeans_frames.h"
#include "shots/temporal_match.h"

#include <algorithm>
#include <string>

namespace mcdenoise {

using OIIO::ImageBuf;
using OIIO::ROI;

namespace {

constexpr const char* op_name = temporal_op;

// Rows of the ROI averaged at a time (`average_frames`).
constexpr int band_rows = 128;

// The values the sums read of every frame: all masked when any is (the
// sums need them alike), the centre's (over `window`) through a masked copy
// if needed.
const SumSource& align_masks(const SumSource& centre, const ROI& window,
                             std::vector<CarriedFrame>& carried, SumSource& centre_copy)
{
    const bool any = centre.masked()
                     || std::any_of(carried.begin(), carried.end(),
                                    [](const CarriedFrame& n) { return n.values.masked(); });
    if (!any)
        return centre;
    for (CarriedFrame& n : carried)
        n.values.mask_all_finite();
    if (centre.masked())
        return centre;
    centre_copy = Planes<float>(window, centre.nchannels());
    for (int ch = 0; ch < centre.nchannels(); ++ch)
        for (int y = window.ybegin; y < window.yend; ++y)
            std::copy_n(centre.from(ch, window.xbegin, y), window.width(),
                        centre_copy.from(ch, window.xbegin, y));
    centre_copy.mask_all_finite();
    return centre_copy;
}

// The excess given back to `band`: at each pixel the mean of every
// frame's excess given out there (the centre's, `centre`, and the carried
// neighbours'), each neighbour weighed as the temporal guide weighs it
// (`guide`; the centre 1), so a firefly's energy is shared among the
// frames that show the same thing there, as its noise is; into `out` (a
// float image over the ROI).
void shot_excess(const Planes<float>& centre, const std::vector<CarriedFrame>& carried,
                 const TemporalGuide& guide, const ROI& band, int nthreads, ImageBuf& out)
{
    parallel_rows(band, nthreads, [&](int y) {
        for (int x = band.xbegin; x < band.xend; ++x) {
            float total = 1.0f;
            for (const Plane<float>& w : guide.weights)
                total += w.at(x, y);
            float* given = static_cast<float*>(out.pixeladdr(x, y));
            for (int c = 0; c < centre.nchannels(); ++c) {
                float sum = *centre.from(c, x, y);
                for (size_t k = 0; k < carried.size(); ++k)
                    sum += guide.weights[k].at(x, y) * *carried[k].excess.from(c, x, y);
                given[c] = sum / total;
            }
        }
    });
}

// The temporal guide, then the NL-means average of `band` over the
// centre's window and the neighbours' (`carried`, over the band's
// regions), into `result`, and the excess the shot gives back to the band
// into `excess`.
void average_band(const PreparedFrameData& centre, std::vector<CarriedFrame>& carried,
                  const ROI& band, int nthreads, ResultPixels& result, ImageBuf& excess)
{
    SumSource centre_copy;
    const SumSource& values = align_masks(centre.planes.values,
                                          temporal_regions(band, centre.frame.clamped.roi()).window,
                                          carried, centre_copy);
    BandMatch match;
    match_band(centre, carried, values, band, nthreads, match);
    const TemporalGuide& guide = match.guide;
    nlmeans_frames(match.frames, guide.colour, guide.variance, centre.frame.clamped.roi(),
                   denoise_patch_radius, centre.frame.strength, nthreads, result);
    shot_excess(centre.given_excess, carried, guide, band, nthreads, excess);
}

// The average of `roi` into `dst` and the excess the shot gives back to it
// into `excess` (a float image over the ROI), band by band of `band_rows`
// rows: the neighbours are carried into the regions of one band at a time,
// so their planes stay small and their memory is reused from band to band.
bool average_frames(ImageBuf& dst, const PreparedFrameData& centre,
                    const std::vector<const PreparedFrameData*>& neighbours,
                    const std::vector<int>& offsets, const ROI& roi, int nthreads,
                    ImageBuf& excess)
{
    const ImageBuf& clamped = centre.frame.clamped;
    const auto inputs       = { centre.input.beauty, &clamped };
    ResultPixels whole, total;  // `dst` allocated over the ROI; the count of empty windows
    if (!begin_result(op_name, dst, clamped, inputs, roi, whole))
        return false;
    std::vector<CarriedFrame> carried;
    for (int y = roi.ybegin; y < roi.yend; y += band_rows) {
        ROI band    = roi;
        band.ybegin = y;
        band.yend   = std::min(roi.yend, y + band_rows);
        carried.clear();
        carry_neighbours(centre, neighbours, offsets, temporal_regions(band, clamped.roi()), nthreads,
                         carried);
        ResultPixels part;
        if (!begin_result(op_name, dst, clamped, inputs, band, part))
            return false;
        average_band(centre, carried, band, nthreads, part, excess);
        if (!finish_result(op_name, dst, part))
            return false;
        total.empty_windows += part.empty_windows;
    }
    return finish_result(op_name, dst, total);
}

}  // namespace

bool denoise(ImageBuf& dst, const PreparedFrame& centre,
             const std::vector<PreparedFrame>& neighbours, const std::vector<int>& offsets,
             ROI roi, int nthreads)
{
    const PreparedFrameData* c = nullptr;
    std::vector<const PreparedFrameData*> ns;
    if (!shot_data(dst, centre, neighbours, offsets, c, ns))
        return false;
    const ImageBuf& beauty = *c->input.beauty;
    if (ns.empty())
        return denoise(dst, beauty, c->input.guides, roi, nthreads);
    if (!resolve_roi(op_name, dst, beauty, roi))
        return false;
    ROI all     = roi;
    all.chbegin = 0;
    all.chend   = beauty.nchannels();
    ImageBuf excess(OIIO::ImageSpec(all, OIIO::TypeDesc::FLOAT));
    if (!average_frames(dst, *c, ns, offsets, roi, nthreads, excess)
        || !give_back_spread(op_name, dst, excess, roi, premultiplied_alpha(beauty), nthreads))
        return false;
    dst.specmod().attribute("mcdenoise:denoise_frames", int(ns.size()) + 1);
    return true;
}

ImageBuf denoise(const PreparedFrame& centre, const std::vector<PreparedFrame>& neighbours,
                 const std::vector<int>& offsets, ROI roi, int nthreads)
{
    return value_form(
        [&](ImageBuf& dst) { return denoise(dst, centre, neighbours, offsets, roi, nthreads); });
}

bool denoise(ImageBuf& dst, const FrameInput& centre, const std::vector<FrameInput>& neighbours,
             const std::vector<int>& offsets, ROI roi, int nthreads)
{
    if (!centre.beauty) {
        dst.errorfmt("{}: the centre frame has no beauty", op_name);
        return false;
    }
    if (!check_neighbours(dst, centre, neighbours, offsets))
        return false;
    if (neighbours.empty())
        return denoise(dst, *centre.beauty, centre.guides, roi, nthreads);
    if (!resolve_roi(op_name, dst, *centre.beauty, roi)
        || !check_frame(dst, centre, "centre frame", centre.beauty->roi()))
        return false;
    // Each frame prepared once, the centre first (its errors first).
    const PreparedFrame c = prepare_frame(centre, nthreads);
    std::vector<PreparedFrame> ns;
    for (const FrameInput& n : neighbours)
        ns.push_back(prepare_frame(n, nthreads));
    return denoise(dst, c, ns, offsets, roi, nthreads);
}

ImageBuf denoise(const FrameInput& centre, const std::vector<FrameInput>& neighbours,
                 const std::vector<int>& offsets, ROI roi, int nthreads)
{
    return value_form(
        [&](ImageBuf& dst) { return denoise(dst, centre, neighbours, offsets, roi, nthreads); });
}

}  // namespace mcdenoise
