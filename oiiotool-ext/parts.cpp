// parts.cpp: reading and writing multi-part OpenEXR files as one image.
#include "parts.h"

#include "error.h"

#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>
#include <OpenImageIO/strutil.h>

#include <set>

namespace mcdtool {

using OIIO::Strutil::fmt::format;

namespace {

/// A part's name ("part 2" if it has none).
std::string part_name(const ImageSpec& spec, size_t index)
{
    const std::string name = spec.get_string_attribute("name");
    return name.empty() ? format("part {}", index) : name;
}

/// The merged name of channel `c` of part `index`.
std::string merged_name(const ImageSpec& spec, size_t index, int c)
{
    const std::string name = spec.channel_name(c);
    if (index == 0 || name.find('.') != std::string::npos)
        return name;
    return part_name(spec, index) + "." + name;
}

/// True if `a` and `b` have the same data and display windows.
bool same_pixels(const ImageSpec& a, const ImageSpec& b)
{
    return a.x == b.x && a.y == b.y && a.z == b.z && a.width == b.width && a.height == b.height
           && a.depth == b.depth && a.full_x == b.full_x && a.full_y == b.full_y
           && a.full_width == b.full_width && a.full_height == b.full_height;
}

}  // namespace

std::vector<Part> file_parts(const std::string& path, std::string_view context)
{
    auto in = OIIO::ImageInput::open(path);
    if (!in) {
        OIIO::geterror();
        return {};
    }
    std::vector<Part> parts;
    std::set<std::string> names;
    int chbegin = 0;
    for (int s = 0; in->seek_subimage(s, 0); ++s) {
        const ImageSpec& spec = in->spec();
        const std::string name = part_name(spec, size_t(s));
        if (spec.deep)
            throw RunError(format("{} : part '{}' of '{}' is deep; deep images are not supported", context, name,
                                  path));
        if (!parts.empty() && !same_pixels(spec, parts.front().spec))
            throw RunError(format("{} : part '{}' of '{}' has another data or display window than part '{}'; the parts must "
                                  "share one",
                                  context, name, path, part_name(parts.front().spec, 0)));
        for (int c = 0; c < spec.nchannels; ++c)
            if (!names.insert(merged_name(spec, size_t(s), c)).second)
                throw RunError(format("{} : '{}' has the channel '{}' twice across its parts", context, path,
                                      merged_name(spec, size_t(s), c)));
        parts.push_back(Part{ spec, chbegin });
        chbegin += spec.nchannels;
    }
    OIIO::geterror();
    if (parts.size() < 2)
        parts.clear();
    return parts;
}

ImageSpec merged_spec(const std::vector<Part>& parts)
{
    ImageSpec spec = parts.front().spec;
    spec.set_format(OIIO::TypeDesc::FLOAT);
    spec.channelformats.clear();
    spec.channelnames.clear();
    for (size_t p = 0; p < parts.size(); ++p)
        for (int c = 0; c < parts[p].spec.nchannels; ++c)
            spec.channelnames.push_back(merged_name(parts[p].spec, p, c));
    spec.nchannels = int(spec.channelnames.size());
    spec.alpha_channel = parts.front().spec.alpha_channel;
    spec.z_channel = parts.front().spec.z_channel;
    spec.erase_attribute("name");
    return spec;
}

ImageBuf read_parts(const std::string& path, const std::vector<Part>& parts, std::string_view context)
{
    ImageBuf merged(merged_spec(parts), OIIO::InitializePixels::No);
    auto in = OIIO::ImageInput::open(path);
    for (size_t p = 0; p < parts.size(); ++p) {
        const ImageSpec& spec = parts[p].spec;
        const bool ok = in && in->read_image(int(p), 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT,
                                             merged.pixeladdr(spec.x, spec.y, spec.z, parts[p].chbegin),
                                             merged.pixel_stride(), merged.scanline_stride());
        if (!ok)
            throw RunError(format("{} : cannot read part '{}' of '{}': {}", context, part_name(spec, p), path,
                                  one_line(in ? in->geterror() : OIIO::geterror())));
    }
    return merged;
}

bool writes_parts(const std::string& path)
{
    auto out = OIIO::ImageOutput::create(path);
    OIIO::geterror();
    return out && out->supports("multiimage");
}

void write_parts(OutputBatch& batch, const std::string& path, const std::vector<Part>& parts,
                 const ImageBuf& pixels, const OutputFormat& format, const std::string& context)
{
    std::vector<ImageSpec> specs;
    std::vector<ImageBuf> images;
    for (const Part& part : parts) {
        ImageSpec spec = part.spec;
        apply_format(spec, format);
        std::vector<int> order;
        for (int c = 0; c < spec.nchannels; ++c)
            order.push_back(part.chbegin + c);
        images.push_back(OIIO::ImageBufAlgo::channels(pixels, spec.nchannels, order));
        specs.push_back(spec);
    }
    batch.write_parts(path, specs, images, context);
}

}  // namespace mcdtool
