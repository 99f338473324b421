// output.cpp: packing the render buffers into one interleaved float image
// and writing it atomically.
#include "output.h"

#include "passes.h"

#include <OpenImageIO/filesystem.h>

#include <cstdio>

#include <unistd.h>

namespace testrender {

namespace {

/// The index of the alpha channel `A`, when there is one: after the 25 others.
constexpr int channel_alpha_index = 25;

}  // namespace

std::vector<std::string> channel_names(const RenderBuffers& b)
{
    std::vector<std::string> names {
        "R",      "G",      "B",      "albedo.R", "albedo.G", "albedo.B", "N.X",
        "N.Y",    "N.Z",    "Z",      "id",       "reflid",   "var.R",    "var.G",
        "var.B",  "A.R",    "A.G",    "A.B",      "B.R",      "B.G",      "B.B",
        "motion.X", "motion.Y", "motion.Z", "motion.W"
    };
    if (!b.alpha.empty())
        names.push_back("A");
    if (!b.passes.empty())
        names.insert(names.end(), pass_channel_names().begin(), pass_channel_names().end());
    return names;
}

OIIO::ImageBuf to_image(const RenderBuffers& b, const std::string& scene_name,
                        const RenderSettings& settings)
{
    const std::vector<std::string> names = channel_names(b);
    const int nch = int(names.size());
    OIIO::ImageSpec spec(b.width, b.height, nch, OIIO::TypeDesc::FLOAT);
    spec.channelnames = names;
    spec.alpha_channel = b.alpha.empty() ? -1 : channel_alpha_index;
    spec.z_channel = 9;
    spec.attribute("compression", "zip");
    spec.attribute("testrender:scene", scene_name);
    spec.attribute("testrender:spp", settings.spp);
    spec.attribute("testrender:seed", int(settings.seed));
    spec.attribute("testrender:frame", settings.frame);
    spec.attribute("testrender:render_seconds", float(b.seconds));
    const double samples = double(b.width) * b.height * settings.spp;
    spec.attribute("testrender:samples_per_second",
                   float(b.seconds > 0 ? samples / b.seconds : 0.0));

    // source buffer and channel count, in file channel order
    // (alpha and passes are empty when absent, and then skipped)
    const std::pair<const std::vector<float>*, int> parts[] = {
        { &b.beauty, 3 },   { &b.albedo, 3 }, { &b.normal, 3 }, { &b.depth, 1 },
        { &b.id, 1 },       { &b.reflid, 1 }, { &b.variance, 3 }, { &b.half_a, 3 },
        { &b.half_b, 3 },   { &b.motion, 4 }, { &b.alpha, 1 },  { &b.passes, pass_channels }
    };
    const size_t npix = size_t(b.width) * size_t(b.height);
    std::vector<float> pixels(npix * size_t(nch));
    for (size_t p = 0; p < npix; ++p) {
        float* dst = &pixels[p * size_t(nch)];
        for (const auto& part : parts)
            if (!part.first->empty())
                for (int c = 0; c < part.second; ++c)
                    *dst++ = (*part.first)[p * size_t(part.second) + size_t(c)];
    }
    OIIO::ImageBuf image(spec);
    image.set_pixels(image.roi(), OIIO::TypeDesc::FLOAT, pixels.data());
    return image;
}

bool write_image(const OIIO::ImageBuf& image, const std::string& path, std::string& error)
{
    const std::string tmp = path + ".tmp" + std::to_string(::getpid())
                            + ".exr";
    if (!image.write(tmp, OIIO::TypeDesc::FLOAT, "openexr")) {
        error = image.geterror();
        std::remove(tmp.c_str());
        return false;
    }
    std::string rename_error;
    if (!OIIO::Filesystem::rename(tmp, path, rename_error)) {
        error = "cannot rename " + tmp + " to " + path + ": " + rename_error;
        std::remove(tmp.c_str());
        return false;
    }
    return true;
}

}  // namespace testrender
