// output.cpp: merging the result into the input's channels, the output
// spec, and atomic (temp file + rename) writes.
#include "output.h"

#include "cleanup.h"
#include "error.h"
#include "input.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <OpenImageIO/strutil.h>

#include <algorithm>
#include <atomic>
#include <cstring>
#include <cstdio>
#include <filesystem>
#include <unistd.h>

namespace mcdtool {

using OIIO::Strutil::fmt::format;
using OIIO::TypeDesc;

namespace {

/// A temp name beside `path` that keeps its extension (OIIO picks the file
/// format from it): "dir/.clean.exr.mcdtool-1234-0.exr".
std::string temp_path(const std::string& path)
{
    static std::atomic<int> counter{ 0 };
    std::filesystem::path final_path(path);
    std::filesystem::path name = format(".{}.mcdtool-{}-{}{}", final_path.filename().string(), int(getpid()),
                                        counter++, final_path.extension().string());
    return (final_path.parent_path() / name).string();
}

/// Pointer to `image`'s float pixels, copying them into `storage` if
/// they are not local contiguous floats.
const float* float_pixels(const ImageBuf& image, std::vector<float>& storage)
{
    if (image.localpixels() && image.spec().format == TypeDesc::FLOAT)
        return static_cast<const float*>(image.localpixels());
    storage.resize(image.spec().image_pixels() * size_t(image.nchannels()));
    image.get_pixels(image.roi(), TypeDesc::FLOAT, storage.data());
    return storage.data();
}

/// `pixels` (float) in the native layout of `spec` (each channel in its
/// own pixel type, as OIIO converts it), the channels of `stored` copied
/// from those images' stored values.
std::vector<unsigned char> native_pixels(const ImageSpec& spec, const ImageBuf& pixels,
                                         const std::map<int, ImageBuf>& stored)
{
    const size_t n = spec.image_pixels();
    const size_t pixel_bytes = spec.pixel_bytes(true);
    std::vector<unsigned char> out(n * pixel_bytes), plane;
    std::vector<float> values(n);
    size_t offset = 0;
    for (int c = 0; c < spec.nchannels; ++c) {
        const TypeDesc type = spec.channelformat(c);
        const size_t size = type.size();
        plane.resize(n * size);
        const auto from = stored.find(c);
        if (from != stored.end()) {
            from->second.get_pixels(from->second.roi(), type, plane.data());
        } else {
            OIIO::ROI channel = pixels.roi();
            channel.chbegin = c;
            channel.chend = c + 1;
            pixels.get_pixels(channel, TypeDesc::FLOAT, values.data());
            OIIO::convert_pixel_values(TypeDesc::FLOAT, values.data(), type, plane.data(), int(n));
        }
        for (size_t i = 0; i < n; ++i)
            std::memcpy(out.data() + i * pixel_bytes + offset, plane.data() + i * size, size);
        offset += size;
    }
    return out;
}

/// Gives `temp` the permissions of the existing file `final_path` it is to
/// replace, so that replacing a file does not change its mode.
void keep_mode(const std::string& final_path, const std::string& temp)
{
    std::error_code error;
    std::filesystem::file_status existing = std::filesystem::status(final_path, error);
    if (!error && std::filesystem::is_regular_file(existing))
        std::filesystem::permissions(temp, existing.permissions(), error);
}

}  // namespace

OutputBatch::~OutputBatch()
{
    for (const Pending& pending : pending_) {
        std::remove(pending.temp.c_str());
        untrack_temp_file(pending.slot);
    }
}

namespace {

/// The error of writing `path` (through `temp`) with `reason`, which names
/// the final path, never the temp file.
RunError write_error(const std::string& path, const std::string& temp, const std::string& context,
                     const std::string& reason)
{
    std::string named = OIIO::Strutil::replace(reason, temp, path, true);
    named = OIIO::Strutil::replace(named, std::filesystem::path(temp).filename().string(),
                                   std::filesystem::path(path).filename().string(), true);
    return RunError(format("{} : cannot write '{}': {}", context, path, one_line(named)));
}

}  // namespace

template<class Fill>
void OutputBatch::write_temp(const std::string& path, const std::string& context, Fill&& fill)
{
    Timer timer;
    std::string temp = temp_path(path);
    auto fail = [&](const std::string& reason) { return write_error(path, temp, context, reason); };
    auto out = OIIO::ImageOutput::create(temp);
    if (!out)
        throw fail(OIIO::geterror());
    pending_.push_back(Pending{ temp, path, track_temp_file(temp) });  // from here on it is removed on failure
    fill(*out, temp, fail);
    if (!out->close())
        throw fail(out->geterror());
    stats_.add_write(timer.seconds());
}

void OutputBatch::write(const std::string& path, const ImageSpec& spec, const ImageBuf& pixels,
                        const std::string& context, const std::map<int, ImageBuf>& stored)
{
    write_temp(path, context, [&](OIIO::ImageOutput& out, const std::string& temp, auto&& fail) {
        ImageSpec file_spec = spec;
        if (!out.supports("channelformats"))
            file_spec.channelformats.clear();
        if (!out.supports("tiles"))
            file_spec.tile_width = file_spec.tile_height = file_spec.tile_depth = 0;
        if (!out.open(temp, file_spec))
            throw fail(out.geterror());
        std::vector<float> storage;
        const bool native = !stored.empty() && !file_spec.channelformats.empty();
        const bool written = native
                                 ? out.write_image(OIIO::TypeUnknown, native_pixels(file_spec, pixels, stored).data())
                                 : out.write_image(TypeDesc::FLOAT, float_pixels(pixels, storage));
        if (!written)
            throw fail(out.geterror());
    });
}

void OutputBatch::write_parts(const std::string& path, const std::vector<ImageSpec>& specs,
                              const std::vector<ImageBuf>& pixels, const std::string& context)
{
    write_temp(path, context, [&](OIIO::ImageOutput& out, const std::string& temp, auto&& fail) {
        std::vector<float> storage;
        for (size_t p = 0; p < specs.size(); ++p) {
            const bool opened = p == 0 ? out.open(temp, int(specs.size()), specs.data())
                                       : out.open(temp, specs[p], OIIO::ImageOutput::AppendSubimage);
            if (!opened || !out.write_image(TypeDesc::FLOAT, float_pixels(pixels[p], storage)))
                throw fail(out.geterror());
        }
    });
}

void OutputBatch::commit()
{
    while (!pending_.empty()) {
        const Pending& pending = pending_.front();
        std::error_code error;
        keep_mode(pending.final_path, pending.temp);
        std::filesystem::rename(pending.temp, pending.final_path, error);
        if (error)
            throw RunError(format("-o : cannot write '{}': {}", pending.final_path, error.message()));
        untrack_temp_file(pending.slot);
        pending_.erase(pending_.begin());
    }
}

namespace {

/// Channels any image format can hold.
constexpr int portable_channels = 4;

/// The input image with channels `beauty` replaced by `result`, as float.
ImageBuf merge_result(const ImageBuf& input, const std::vector<int>& beauty, const ImageBuf& result)
{
    ImageBuf merged;
    if (!merged.copy(input, TypeDesc::FLOAT))
        throw RunError(format("-o : cannot copy the input: {}", one_line(merged.geterror())));
    OIIO::ROI window = result.roi();
    std::vector<float> plane(window.npixels());
    for (size_t k = 0; k < beauty.size(); ++k) {
        OIIO::ROI from = window;
        from.chbegin = int(k);
        from.chend = int(k) + 1;
        OIIO::ROI to = window;
        to.chbegin = beauty[k];
        to.chend = beauty[k] + 1;
        if (!result.get_pixels(from, TypeDesc::FLOAT, plane.data())
            || !merged.set_pixels(to, TypeDesc::FLOAT, plane.data()))
            throw RunError(format("-o : cannot merge the result: {}", one_line(merged.geterror())));
    }
    return merged;
}

/// The spec to write for `input`, with `format` applied.
ImageSpec output_spec(const ImageBuf& input, const OutputFormat& format)
{
    ImageSpec spec = input.nativespec();
    apply_format(spec, format);
    return spec;
}

/// True if the format chosen by `path`'s extension holds any channel count
/// under its channels' names. Of OpenImageIO's writers only OpenEXR stores
/// channel names; TIFF, DPX, SGI and the like hold the channels but read
/// them back as "channel3", "channel4", ...
bool keeps_named_channels(const std::string& path)
{
    auto out = OIIO::ImageOutput::create(path);
    OIIO::geterror();  // an unknown extension is reported when writing
    return !out || (out->supports("nchannels") && std::string(out->format_name()) == "openexr");
}

}  // namespace

void apply_format(ImageSpec& spec, const OutputFormat& format)
{
    if (!format.data_format.empty()) {
        spec.set_format(TypeDesc(format.data_format));
        spec.channelformats.clear();
    }
    if (!format.compression.empty())
        spec.attribute("compression", format.compression);
}

OutputImage compose_output(const ImageBuf& input, const IntegerChannels& integers, const std::vector<int>& beauty,
                           const ImageBuf& result, const OutputFormat& format, const std::string& path)
{
    OutputImage output;
    output.spec = output_spec(input, format);
    if (input.nchannels() <= portable_channels || keeps_named_channels(path)) {
        output.pixels = merge_result(input, beauty, result);
        for (const auto& [c, stored] : integers)
            if (!output.spec.channelformats.empty() && output.spec.channelformat(c).size() >= 4
                && std::find(beauty.begin(), beauty.end(), c) == beauty.end())
                output.stored[c] = stored;
        return output;
    }
    output.beauty_only = true;
    output.pixels = result;
    std::vector<std::string> names;
    for (int c : beauty)
        names.push_back(input.spec().channel_name(c));
    output.spec.nchannels = int(beauty.size());
    output.spec.channelnames = names;
    output.spec.channelformats.clear();
    output.spec.alpha_channel = -1;
    output.spec.z_channel = -1;
    return output;
}

void prepare_output_path(const std::string& option, const std::string& path, bool force)
{
    namespace fs = std::filesystem;
    std::error_code error;
    fs::file_status existing = fs::status(path, error);
    if (fs::is_directory(existing))
        throw RunError(format("{} : cannot write '{}': it is a directory", option, path));
    const fs::perms writable = fs::perms::owner_write | fs::perms::group_write | fs::perms::others_write;
    if (!force && fs::is_regular_file(existing) && (existing.permissions() & writable) == fs::perms::none)
        throw RunError(format("{} : '{}' is write-protected; add --force to replace it", option, path));
    if (!OIIO::ImageOutput::create(path))
        throw RunError(format("{} : cannot write '{}': {}", option, path, one_line(OIIO::geterror())));
    fs::path folder = fs::path(path).parent_path();
    if (!folder.empty() && !fs::is_directory(folder) && !fs::create_directories(folder, error) && error)
        throw RunError(format("{} : cannot create the folder '{}' for '{}': {}", option, folder.string(), path,
                              error.message()));
}

bool same_file(const std::string& a, const std::string& b)
{
    namespace fs = std::filesystem;
    std::error_code error;
    if (fs::exists(a, error) && fs::exists(b, error))
        return fs::equivalent(a, b, error);
    return fs::weakly_canonical(a, error) == fs::weakly_canonical(b, error);
}

}  // namespace mcdtool
