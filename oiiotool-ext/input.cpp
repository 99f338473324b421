// input.cpp: image reading with errors that name the file.
#include "input.h"

#include "channel_names.h"

#include "error.h"
#include "memory_limit.h"
#include "parts.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <OpenImageIO/strutil.h>

#include <algorithm>
#include <memory>
#include <cstdio>

namespace mcdtool {

using OIIO::Strutil::fmt::format;

namespace {

/// Every channel of `image` that its file stores as integers, read in its
/// stored type from one opening of the file.
IntegerChannels read_integer_channels(const ImageBuf& image)
{
    IntegerChannels channels;
    std::unique_ptr<OIIO::ImageInput> in;
    const std::string path = image.name();
    for (int c = 0; c < image.nchannels(); ++c) {
        if (!stored_as_integers(image, c))
            continue;
        const OIIO::TypeDesc type = image.nativespec().channelformat(c);
        OIIO::ImageSpec spec = extracted_spec(image.spec(), { c });
        spec.set_format(type);
        ImageBuf stored(spec, OIIO::InitializePixels::No);
        if (!in)
            in = OIIO::ImageInput::open(path);
        if (!in || !in->read_image(0, 0, c, c + 1, type, stored.localpixels()))
            throw RunError(format("cannot read channel {} of '{}': {}", spec.channelnames[0], path,
                                  one_line(in ? in->geterror() : OIIO::geterror())));
        channels.emplace(c, std::move(stored));
    }
    return channels;
}

/// The one-line reason `image` could not be read.
std::string read_error(const ImageBuf& image)
{
    std::string reason = one_line(image.geterror());
    std::string global = one_line(OIIO::geterror());
    return reason.empty() ? (global.empty() ? "unknown error" : global) : reason;
}

}  // namespace

ImageBuf read_image(const std::string& path, std::string_view context, uint64_t memory_limit)
{
    if (!OIIO::Filesystem::exists(path))
        throw RunError(format("{} : cannot read '{}': no such file", context, path));
    if (OIIO::Filesystem::is_directory(path))
        throw RunError(format("{} : cannot read '{}': it is a directory", context, path));
    ImageBuf image;
    if (!image.init_spec(path, 0, 0) || image.has_error())
        throw RunError(format("{} : cannot read '{}': {}", context, path, read_error(image)));
    const OIIO::ImageSpec& spec = image.spec();
    if (spec.deep)
        throw RunError(format("{} : cannot read '{}': deep images are not supported", context, path));
    require_memory(float_bytes(spec.image_pixels(), uint64_t(std::max(spec.nchannels, 0))), memory_limit,
                   std::string(context),
                   format("'{}' ({} x {}, {} channels, as float)", path, spec.width, spec.height, spec.nchannels));
    if (image.nsubimages() > 1) {
        const std::vector<Part> parts = file_parts(path, context);
        const ImageSpec merged = merged_spec(parts);
        require_memory(float_bytes(merged.image_pixels(), uint64_t(merged.nchannels)), memory_limit,
                       std::string(context),
                       format("'{}' ({} x {}, {} channels in {} parts, as float)", path, merged.width, merged.height,
                              merged.nchannels, parts.size()));
        return read_parts(path, parts, context);
    }
    if (!image.read(0, 0, true, OIIO::TypeDesc::FLOAT) || image.has_error())
        throw RunError(format("{} : cannot read '{}': {}", context, path, read_error(image)));
    return image;
}

void warn_if_display_referred(const ImageBuf& image, std::string_view context)
{
    const OIIO::ImageSpec& spec = image.nativespec();
    const std::string format_name = image.file_format_name();
    const bool display_format = format_name == "png" || format_name == "jpeg";
    const bool srgb = OIIO::Strutil::iequals(spec.get_string_attribute("oiio:ColorSpace"), "sRGB");
    if (spec.format != OIIO::TypeDesc::UINT8 || !spec.channelformats.empty() || !(display_format || srgb))
        return;
    std::fprintf(stderr,
                 "mcdtool WARNING: %s : '%s' is 8-bit display-referred (%s); the filters assume linear light, "
                 "so denoise the renderer's linear EXR, or convert first (oiiotool IN --colorconvert sRGB "
                 "linear -d half -o IN.exr)\n",
                 std::string(context).c_str(), image.name().c_str(), srgb ? "sRGB" : format_name.c_str());
}

bool stored_as_integers(const ImageBuf& image, int c)
{
    const OIIO::TypeDesc type = image.nativespec().channelformat(c);
    return type.basetype >= OIIO::TypeDesc::UINT8 && type.basetype <= OIIO::TypeDesc::INT64;
}

const ImageBuf& ImageFiles::get(const std::string& path, std::string_view context)
{
    auto found = images_.find(path);
    if (found != images_.end())
        return found->second;
    Timer timer;
    ImageBuf image = read_image(path, context, memory_limit_);
    stats_.add_read(timer.seconds());
    return images_.emplace(path, std::move(image)).first->second;
}

const IntegerChannels& ImageFiles::integer_channels(const ImageBuf& image)
{
    auto found = integers_.find(&image);
    if (found != integers_.end())
        return found->second;
    return integers_.emplace(&image, read_integer_channels(image)).first->second;
}

}  // namespace mcdtool
