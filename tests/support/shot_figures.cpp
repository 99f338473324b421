// shot_figures.cpp: running every method on the shot set's shots and
// measuring them.
#include "support/shot_figures.h"

#include "support/shot.h"

#include <mcdenoise/mcdenoise.h>

#include <functional>
#include <sstream>

namespace testimg {

using OIIO::ImageBuf;

namespace {

// The images of one method for frame t.
using Method = std::function<ImageBuf(int t)>;

struct Methods {
    std::vector<ImageBuf> denoised;
    std::vector<Method> all;  // in the order of method_names()
};

Methods make_methods(const Shot& shot, int n)
{
    Methods m { per_frame(shot), {} };
    const std::vector<ImageBuf>* d = &m.denoised;
    const Shot* s = &shot;
    m.all = {
        [s](int t) { return s->frames[size_t(t - s->first)].beauty; },
        [s, d](int t) { return (*d)[size_t(t - s->first)]; },
        [s, d, n](int t) { return baseline(*s, *d, t, n); },
        [s, n](int t) { return cross_frame(*s, t, n, true); },
        [s, n](int t) { return cross_frame(*s, t, n, false); },
    };
    return m;
}

std::vector<MethodFigures*> members(ShotFigures& f)
{
    return { &f.raw, &f.per_frame, &f.baseline, &f.cross, &f.cross_still };
}

// Each method's images of the evaluated frames against `refs`
// (sequence_metrics.h), the region relMSE over `masks` (one per evaluated
// frame, or none), and the flicker when `still`.
void measure(ShotFigures& f, const Shot& shot, const std::vector<ImageBuf>& refs,
             const std::vector<ImageBuf>& masks, bool still = false)
{
    const Methods m = make_methods(shot, f.n);
    const std::vector<MethodFigures*> out = members(f);
    std::vector<const ImageBuf*> ref_frames;
    for (const ImageBuf& r : refs)
        ref_frames.push_back(&r);
    for (size_t k = 0; k < m.all.size(); ++k) {
        std::vector<ImageBuf> images;
        for (int t : f.evaluated)
            images.push_back(m.all[k](t));
        std::vector<const ImageBuf*> frames;
        for (const ImageBuf& img : images)
            frames.push_back(&img);
        const mcdenoise::SequenceComparison c = mcdenoise::compare_sequence(frames, ref_frames);
        MethodFigures& mf = *out[k];
        mf.frame_rel_mse  = c.frame_rel_mse;
        mf.rel_mse        = c.mean_rel_mse;
        if (images.size() > 1)
            mf.temporal = c.temporal_error;
        if (still)
            mf.flicker = c.flicker;
        for (size_t i = 0; i < images.size() && !masks.empty(); ++i)
            mf.region += masked_rel_mse(images[i], refs[i], masks[i]) / double(images.size());
        f.pictures.push_back(images.back());
    }
    f.pictures.push_back(refs.back());
}

std::vector<int> frame_range(int first, int last)
{
    std::vector<int> v;
    for (int t = first; t <= last; ++t)
        v.push_back(t);
    return v;
}

}  // namespace

const std::vector<std::string>& method_names()
{
    static const std::vector<std::string> names { "raw 16 spp", "per-frame denoise",
                                                  "baseline", "cross-frame",
                                                  "cross-frame, no motion" };
    return names;
}

std::vector<const MethodFigures*> methods(const ShotFigures& f)
{
    return { &f.raw, &f.per_frame, &f.baseline, &f.cross, &f.cross_still };
}

ShotFigures static_figures(const std::string& dir)
{
    ShotFigures f { "shot_static", "", 3, frame_range(0, 7), {}, {}, {}, {}, {}, {} };
    const Shot shot = read_shot(dir, f.shot, 0, 7);
    const ImageBuf ref = read_beauty(dir + "/shot_static_ref_f0.exr", f.error);
    if (!shot.error.empty() || !f.error.empty()) {
        f.error += shot.error;
        return f;
    }
    measure(f, shot, std::vector<ImageBuf>(f.evaluated.size(), ref), {}, true);
    return f;
}

ShotFigures truck_figures(const std::string& dir)
{
    ShotFigures f { "shot_truck", "", 2, frame_range(2, 4), {}, {}, {}, {}, {}, {} };
    const Shot shot = read_shot(dir, f.shot, 0, 6);
    std::vector<ImageBuf> refs, masks;
    for (int t : f.evaluated) {
        refs.push_back(read_beauty(dir + "/shot_truck_ref_f" + std::to_string(t) + ".exr",
                                   f.error));
        if (shot.error.empty())
            masks.push_back(disoccluded_pixels(shot, t));
    }
    if (!shot.error.empty() || !f.error.empty()) {
        f.error += shot.error;
        return f;
    }
    measure(f, shot, refs, masks);
    return f;
}

ShotFigures object_figures(const std::string& dir)
{
    ShotFigures f { "shot_object", "", 2, { 2 }, {}, {}, {}, {}, {}, {} };
    const Shot shot = read_shot(dir, f.shot, 0, 4);
    const ImageBuf ref = read_beauty(dir + "/shot_object_ref_f2.exr", f.error);
    std::vector<ImageBuf> others;
    for (int t : { 0, 1, 3, 4 })
        others.push_back(read_beauty(dir + "/shot_object_256_f" + std::to_string(t) + ".exr",
                                     f.error));
    if (!shot.error.empty() || !f.error.empty()) {
        f.error += shot.error;
        return f;
    }
    // The moving sphere's id (shots.cpp).
    constexpr float sphere_id = 20.0f;
    measure(f, shot, { ref }, { left_behind_pixels(shot, 2, sphere_id, ref, others) });
    return f;
}

std::string static_pixel_csv(const std::string& dir, int x, int y, int c)
{
    std::string error;
    const Shot shot = read_shot(dir, "shot_static", 0, 7);
    const ImageBuf ref = read_beauty(dir + "/shot_static_ref_f0.exr", error);
    if (!shot.error.empty() || !error.empty())
        return {};
    const Methods m = make_methods(shot, 3);
    std::ostringstream out;
    out << "frame,raw,per_frame,cross,reference\n";
    for (int t = 0; t <= 7; ++t)
        out << t << "," << m.all[0](t).getchannel(x, y, 0, c) << ","
            << m.all[1](t).getchannel(x, y, 0, c) << "," << m.all[3](t).getchannel(x, y, 0, c)
            << "," << ref.getchannel(x, y, 0, c) << "\n";
    return out.str();
}

}  // namespace testimg
