// shot.cpp: reading the shot set, the results compared on it, the shot
// metrics and the masks of the regions they look at.
#include "support/shot.h"

#include "support/warped_average.h"

#include <mcdenoise/mcdenoise.h>

#include <OpenImageIO/imagebufalgo.h>

#include <cmath>
#include <cstdlib>

namespace testimg {

using OIIO::ImageBuf;
using OIIO::ROI;
namespace IBA = OIIO::ImageBufAlgo;

mcdenoise::FrameInput Shot::input(int t, bool motion) const
{
    const Render& r = frames[size_t(t - first)];
    mcdenoise::FrameInput f { &r.beauty, r.guides() };
    f.guides.motion = motion ? &r.motion : nullptr;
    return f;
}

std::vector<int> Shot::neighbours(int t, int n) const
{
    std::vector<int> out;
    for (int k = -n; k <= n; ++k)
        if (k != 0 && t + k >= first && t + k <= last())
            out.push_back(t + k);
    return out;
}

std::string shotset_dir(const std::string& fallback)
{
    const char* env = std::getenv("MCD_SHOTSET_DIR");
    return env && *env ? env : fallback;
}

Shot read_shot(const std::string& dir, const std::string& shot, int first, int last)
{
    Shot s;
    s.first = first;
    for (int t = first; t <= last; ++t) {
        s.frames.push_back(read_render(dir + "/" + shot + "_16_f" + std::to_string(t) + ".exr"));
        if (s.error.empty())
            s.error = s.frames.back().error;
    }
    return s;
}

ImageBuf read_beauty(const std::string& path, std::string& error)
{
    Render r = read_render(path);
    if (error.empty())
        error = r.error;
    return r.beauty;
}

std::vector<ImageBuf> per_frame(const Shot& shot)
{
    std::vector<ImageBuf> out;
    for (const Render& r : shot.frames)
        out.push_back(mcdenoise::denoise(r.beauty, r.guides()));
    return out;
}

ImageBuf cross_frame(const Shot& shot, int t, int n, bool motion, int nthreads)
{
    std::vector<mcdenoise::FrameInput> inputs;
    std::vector<int> offsets;
    for (int q : shot.neighbours(t, n)) {
        inputs.push_back(shot.input(q, motion));
        offsets.push_back(q - t);
    }
    return mcdenoise::denoise(shot.input(t, motion), inputs, offsets, {}, nthreads);
}

ImageBuf baseline(const Shot& shot, const std::vector<ImageBuf>& denoised, int t, int n)
{
    std::vector<mcdenoise::FrameInput> inputs;
    std::vector<const ImageBuf*> results;
    std::vector<int> offsets;
    for (int q : shot.neighbours(t, n)) {
        inputs.push_back(shot.input(q, true));
        results.push_back(&denoised[size_t(q - shot.first)]);
        offsets.push_back(q - t);
    }
    ImageBuf out;
    if (!mcdenoise::warped_average(out, shot.input(t, true), denoised[size_t(t - shot.first)],
                                   inputs, results, offsets))
        out.errorfmt("baseline: {}", out.geterror());
    return out;
}

ImageBuf pixel_mask(const ImageBuf& like, const std::function<bool(int, int)>& keep)
{
    const ROI roi = like.roi();
    ImageBuf mask(OIIO::ImageSpec(roi.width(), roi.height(), 1, OIIO::TypeDesc::FLOAT));
    mask.set_origin(roi.xbegin, roi.ybegin);
    for (int y = roi.ybegin; y < roi.yend; ++y)
        for (int x = roi.xbegin; x < roi.xend; ++x) {
            const float v = keep(x, y) ? 1.0f : 0.0f;
            mask.setpixel(x, y, &v, 1);
        }
    return mask;
}

ImageBuf disoccluded_pixels(const Shot& shot, int t)
{
    const Render& r = shot.frames[size_t(t - shot.first)];
    const ROI roi   = r.beauty.roi();
    return pixel_mask(r.beauty, [&](int x, int y) {
        float m[4];
        r.motion.getpixel(x, y, m, 4);
        const float id = r.object_id.getchannel(x, y, 0, 0);
        // Cycles' Vector: (x + X, y - Y) in frame t - 1, (x - Z, y + W) in t + 1.
        const float to[2][3] = { { m[0], -m[1], -1.0f }, { -m[2], m[3], 1.0f } };
        for (const auto& v : to) {
            const int q = t + int(v[2]);
            if (q < shot.first || q > shot.last())
                continue;
            const int qx = int(std::floor(float(x) + v[0] + 0.5f));
            const int qy = int(std::floor(float(y) + v[1] + 0.5f));
            if (qx < roi.xbegin || qx >= roi.xend || qy < roi.ybegin || qy >= roi.yend
                || shot.frames[size_t(q - shot.first)].object_id.getchannel(qx, qy, 0, 0) != id)
                return true;
        }
        return false;
    });
}

ImageBuf left_behind_pixels(const Shot& shot, int t, float object, const ImageBuf& reference,
                            const std::vector<ImageBuf>& others)
{
    const Render& r = shot.frames[size_t(t - shot.first)];
    return pixel_mask(r.beauty, [&](int x, int y) {
        if (r.object_id.getchannel(x, y, 0, 0) == object)
            return false;
        for (const ImageBuf& o : others)
            for (int c = 0; c < 3; ++c) {
                const float v = reference.getchannel(x, y, 0, c);
                if (std::fabs(o.getchannel(x, y, 0, c) - v) > 0.1f * v + 0.01f)
                    return true;
            }
        return false;
    });
}

}  // namespace testimg
