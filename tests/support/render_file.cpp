// render_file.cpp: reading testrender files and naming the report's filters.
#include "render_file.h"

#include <mcdenoise/mcdenoise.h>

#include <OpenImageIO/imagebufalgo.h>

namespace testimg {

using OIIO::ImageBuf;
namespace IBA = OIIO::ImageBufAlgo;

namespace {

ImageBuf channels_named(const ImageBuf& src, const std::vector<std::string>& names,
                        std::string& error)
{
    std::vector<int> order;
    for (const std::string& n : names) {
        const int c = src.spec().channelindex(n);
        if (c < 0 && error.empty())
            error = "no channel " + n + " in " + std::string(src.name());
        order.push_back(c);
    }
    if (!error.empty())
        return {};
    return IBA::channels(src, int(order.size()), order);
}

}  // namespace

Render read_render(const std::string& path)
{
    Render r;
    ImageBuf file(path);
    if (!file.read(0, 0, true, OIIO::TypeDesc::FLOAT)) {
        r.error = file.geterror();
        return r;
    }
    r.beauty     = channels_named(file, { "R", "G", "B" }, r.error);
    r.object_id  = channels_named(file, { "id" }, r.error);
    r.reflect_id = channels_named(file, { "reflid" }, r.error);
    r.normal     = channels_named(file, { "N.X", "N.Y", "N.Z" }, r.error);
    r.depth      = channels_named(file, { "Z" }, r.error);
    r.albedo     = channels_named(file, { "albedo.R", "albedo.G", "albedo.B" }, r.error);
    r.variance   = channels_named(file, { "var.R", "var.G", "var.B" }, r.error);
    r.half_a     = channels_named(file, { "A.R", "A.G", "A.B" }, r.error);
    r.half_b     = channels_named(file, { "B.R", "B.G", "B.B" }, r.error);
    r.motion = channels_named(file, { "motion.X", "motion.Y", "motion.Z", "motion.W" }, r.error);
    return r;
}

ImageBuf best_chain(const Render& r)
{
    return mcdenoise::gaussian(mcdenoise::object_median(r.beauty, r.object_id, 7), 3);
}

std::vector<NamedFilter> report_filters()
{
    std::vector<NamedFilter> f;
    for (int s : { 3, 7 }) {
        const std::string n = " " + std::to_string(s);
        f.push_back({ "mean" + n, [s](const Render& r) { return mcdenoise::mean(r.beauty, s); } });
        f.push_back({ "median" + n, [s](const Render& r) { return mcdenoise::median(r.beauty, s); } });
        f.push_back({ "gaussian" + n,
                      [s](const Render& r) { return mcdenoise::gaussian(r.beauty, s); } });
        f.push_back({ "object_mean" + n, [s](const Render& r) {
                         return mcdenoise::object_mean(r.beauty, r.object_id, s);
                     } });
        f.push_back({ "object_median" + n, [s](const Render& r) {
                         return mcdenoise::object_median(r.beauty, r.object_id, s);
                     } });
        f.push_back({ "object_gaussian" + n, [s](const Render& r) {
                         return mcdenoise::object_gaussian(r.beauty, r.object_id, s);
                     } });
        f.push_back({ "brdf_mean" + n, [s](const Render& r) {
                         return mcdenoise::brdf_mean(r.beauty, r.object_id, r.reflect_id, s);
                     } });
        f.push_back({ "brdf_gaussian" + n, [s](const Render& r) {
                         return mcdenoise::brdf_gaussian(r.beauty, r.object_id, r.reflect_id, s);
                     } });
        f.push_back({ "brdf_median" + n, [s](const Render& r) {
                         return mcdenoise::brdf_median(r.beauty, r.object_id, r.reflect_id, s);
                     } });
        f.push_back({ "normal_mean" + n, [s](const Render& r) {
                         return mcdenoise::normal_mean(r.beauty, r.object_id, r.normal, s);
                     } });
        f.push_back({ "normal_gaussian" + n, [s](const Render& r) {
                         return mcdenoise::normal_gaussian(r.beauty, r.object_id, r.normal, s);
                     } });
    }
    f.push_back({ "dof 10 0", [](const Render& r) {
                     return mcdenoise::dof(r.beauty, r.object_id, r.depth, 10, 0);
                 } });
    f.push_back({ "object_median 7 + gaussian 3", best_chain });
    return f;
}

double masked_rel_mse(const ImageBuf& result, const ImageBuf& reference, const ImageBuf& mask)
{
    const OIIO::ROI roi = reference.roi();
    ImageBuf inside     = result;
    int64_t count = 0, total = 0;
    for (int y = roi.ybegin; y < roi.yend; ++y)
        for (int x = roi.xbegin; x < roi.xend; ++x, ++total) {
            if (mask.getchannel(x, y, 0, 0) != 0.0f) {
                ++count;
                continue;
            }
            float px[16];
            reference.getpixel(x, y, px, 16);
            inside.setpixel(x, y, px, 16);
        }
    if (count == 0)
        return 0.0;
    return mcdenoise::rel_mse(inside, reference) * double(total) / double(count);
}

ImageBuf single_object_pixels(const ImageBuf& object_id, int size)
{
    const OIIO::ROI roi = object_id.roi();
    ImageBuf mask(OIIO::ImageSpec(roi.width(), roi.height(), 1, OIIO::TypeDesc::FLOAT));
    mask.set_origin(roi.xbegin, roi.ybegin);
    const int r = size / 2;
    for (int y = roi.ybegin; y < roi.yend; ++y)
        for (int x = roi.xbegin; x < roi.xend; ++x) {
            const float id = object_id.getchannel(x, y, 0, 0);
            bool single    = true;
            for (int qy = std::max(roi.ybegin, y - r); qy < std::min(roi.yend, y + r + 1); ++qy)
                for (int qx = std::max(roi.xbegin, x - r); qx < std::min(roi.xend, x + r + 1); ++qx)
                    single &= object_id.getchannel(qx, qy, 0, 0) == id;
            mask.setpixel(x, y, &(const float&)(single ? 1.0f : 0.0f), 1);
        }
    return mask;
}

}  // namespace testimg
