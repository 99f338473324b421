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
#include "shots/frame_warp.h"
#include "shots/shot_variance.h"
#include "shots/temporal_frame.h"
#include "shots/temporal_guide.h"

#include <algorithm>
#include <numeric>
#include <string>

namespace mcdenoise {

using OIIO::ImageBuf;
using OIIO::ROI;

namespace {

constexpr const char* op_name = temporal_op;

// Rows of the ROI averaged at a time (`average_frames`).
constexpr int band_rows = 128;

// The regions of the centre frame (data window `dw`) the average reads to
// filter `roi`, as `nlmeans` reads them: the colour (the patches grown by
// one, and by the box `shot_variance` compares frames over), the variance
// (the patches) and the features and values (the search windows).
CarryRegions regions(const ROI& roi, const ROI& dw)
{
    const ROI patches = grow_and_clip(roi, denoise_search_radius + denoise_patch_radius, dw);
    return { grow_and_clip(patches, 1 + agreement_radius, dw), patches,
             grow_and_clip(roi, denoise_search_radius, dw) };
}

// Which guides a frame has that `denoise` reads, as flags in the order of
// `Guides`.
std::string guide_set(const Guides& g)
{
    std::string s;
    for (const ImageBuf* p : { g.normal, g.depth, g.albedo, g.variance, g.half_a, g.half_b })
        s += p ? '1' : '0';
    return s;
}

bool same_window(const ROI& a, const ROI& b)
{
    return a.xbegin == b.xbegin && a.xend == b.xend && a.ybegin == b.ybegin && a.yend == b.yend
           && a.zbegin == b.zbegin && a.zend == b.zend;
}

bool check_neighbours(ImageBuf& dst, const FrameInput& centre,
                      const std::vector<FrameInput>& neighbours, const std::vector<int>& offsets)
{
    if (neighbours.size() != offsets.size()) {
        dst.errorfmt("{}: {} neighbour frames but {} offsets", op_name, neighbours.size(),
                     offsets.size());
        return false;
    }
    for (size_t i = 0; i < neighbours.size(); ++i) {
        const std::string what = "neighbour frame at offset " + std::to_string(offsets[i]);
        if (offsets[i] == 0
            || std::count(offsets.begin(), offsets.end(), offsets[i]) > 1) {
            dst.errorfmt("{}: {}: offsets must be non-zero and distinct", op_name, what);
            return false;
        }
        const FrameInput& n = neighbours[i];
        if (!check_frame(dst, n, what, n.beauty ? n.beauty->roi() : ROI()))
            return false;
        if (!same_window(n.beauty->roi(), centre.beauty->roi())
            || n.beauty->nchannels() != centre.beauty->nchannels()) {
            dst.errorfmt("{}: {}: data window or channel count differs from the centre frame's",
                         op_name, what);
            return false;
        }
        if (guide_set(n.guides) != guide_set(centre.guides)) {
            dst.errorfmt("{}: {}: has not the centre frame's set of guides", op_name, what);
            return false;
        }
    }
    return true;
}

// Carry every neighbour into the centre's regions `r`, in the order of
// their offsets, so the sums do not depend on the order they are listed
// in.
void carry_neighbours(const PreparedFrameData& centre,
                      const std::vector<const PreparedFrameData*>& neighbours,
                      const std::vector<int>& offsets, const CarryRegions& r, int nthreads,
                      std::vector<CarriedFrame>& carried)
{
    std::vector<const GuideChannels*> motions;
    for (const PreparedFrameData* f : neighbours)
        motions.push_back(f->has_motion() ? &f->motion : nullptr);
    motions.insert(motions.begin(), centre.has_motion() ? &centre.motion : nullptr);
    std::vector<size_t> order(neighbours.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::sort(order.begin(), order.end(),
              [&](size_t a, size_t b) { return offsets[a] < offsets[b]; });
    for (size_t i : order)
        carried.push_back(carry_frame(neighbours[i]->planes, neighbours[i]->given_excess,
                                      neighbours[i]->input.beauty->roi(),
                                      motion_steps(motions, offsets, offsets[i]), offsets[i], r,
                                      nthreads));
}

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
    const FeatureInputs& c = centre.planes;
    const ROI dw           = centre.frame.clamped.roi();
    SumSource centre_copy;
    const SumSource& values = align_masks(c.values, regions(band, dw).window, carried,
                                          centre_copy);
    const int radius = centre.has_motion() ? temporal_search_radius
                                           : temporal_still_search_radius;
    std::vector<NlmFrame> frames { { &c.colour, &c.variance, &c.features, &c.features, &values,
                                     nullptr, denoise_search_radius, true } };
    for (const CarriedFrame& n : carried)
        frames.push_back({ &n.colour, &n.variance, &n.features, &c.features, &n.values,
                           &n.usable, radius, false });
    std::vector<const Plane<float>*> faithful;
    for (const CarriedFrame& n : carried)
        faithful.push_back(&n.faithful);
    const std::vector<VarianceField> variances
        = shot_variance(frames, faithful, regions(band, dw).variance, dw, nthreads);
    for (size_t k = 0; k < variances.size(); ++k)
        frames[k].variance = &variances[k];
    // The patches and features every candidate is compared with: the
    // centre's, averaged over the frames that match them.
    const float strength      = centre.frame.strength;
    const TemporalGuide guide = temporal_guide(frames, grow_and_clip(band, denoise_patch_radius, dw),
                                               dw, denoise_patch_radius, strength, nthreads);
    for (NlmFrame& f : frames)
        f.centre_features = &guide.features;
    nlmeans_frames(frames, guide.colour, guide.variance, dw, denoise_patch_radius, strength,
                   nthreads, result);
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
        carry_neighbours(centre, neighbours, offsets, regions(band, clamped.roi()), nthreads,
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

// A prepared frame's data, or an error naming it (`what`).
const PreparedFrameData* prepared_data(ImageBuf& dst, const PreparedFrame& f,
                                       const std::string& what)
{
    if (!f.error.empty())
        dst.errorfmt("{}: {}: {}", op_name, what, f.error);
    else if (!f.data)
        dst.errorfmt("{}: {}: not prepared", op_name, what);
    return f.data.get();
}

}  // namespace

bool denoise(ImageBuf& dst, const PreparedFrame& centre,
             const std::vector<PreparedFrame>& neighbours, const std::vector<int>& offsets,
             ROI roi, int nthreads)
{
    const PreparedFrameData* c = prepared_data(dst, centre, "centre frame");
    std::vector<const PreparedFrameData*> ns;
    std::vector<FrameInput> inputs;
    for (size_t i = 0; c && i < neighbours.size(); ++i) {
        const std::string what = i < offsets.size()
                                     ? "neighbour frame at offset " + std::to_string(offsets[i])
                                     : "neighbour frame " + std::to_string(i);
        ns.push_back(prepared_data(dst, neighbours[i], what));
        if (!ns.back())
            return false;
        inputs.push_back(ns.back()->input);
    }
    if (!c || !check_neighbours(dst, c->input, inputs, offsets))
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
