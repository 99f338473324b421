// channels.cpp: beauty and guide discovery, channel selection and
// extraction.
#include "channels.h"

#include "cryptomatte.h"

#include "error.h"

#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imagebufalgo_util.h>
#include <OpenImageIO/strutil.h>

#include <algorithm>

namespace mcdtool {

using OIIO::Strutil::fmt::format;
namespace Strutil = OIIO::Strutil;

namespace {

/// Pass names that hold the beauty, preferred first (after bare R,G,B):
/// Cycles' Combined, then RenderMan's Ci (written bare R,G,B with "asrgba").
const std::vector<std::string> beauty_passes = { "Combined", "Ci", "rgba", "beauty", "color" };
/// The alpha component, kept out of the default beauty (it passes through).
const std::string alpha = "A";

}  // namespace

std::vector<int> pass_channels(const ImageSpec& spec, const std::string& layer, const std::string& pass)
{
    std::vector<int> indices;
    for (int c = 0; c < spec.nchannels; ++c) {
        ChannelName name = split_name(spec.channel_name(c));
        if (name.layer == layer && Strutil::iequals(name.pass, pass))
            indices.push_back(c);
    }
    return indices;
}

namespace {

/// `indices` without the alpha channel, unless that would leave nothing.
std::vector<int> without_alpha(const ImageSpec& spec, const std::vector<int>& indices)
{
    std::vector<int> kept;
    for (int c : indices)
        if (split_name(spec.channel_name(c)).component != alpha)
            kept.push_back(c);
    return kept.empty() ? indices : kept;
}

/// The default beauty: bare R,G,B (or Y), else the first Combined-like pass
/// (`beauty_passes`).
std::vector<int> find_beauty(const ImageSpec& spec)
{
    std::vector<int> bare = pass_channels(spec, "", "");
    if (!bare.empty())
        return without_alpha(spec, bare);
    for (const std::string& pass : beauty_passes)
        for (int c = 0; c < spec.nchannels; ++c) {
            ChannelName name = split_name(spec.channel_name(c));
            if (Strutil::iequals(name.pass, pass))
                return without_alpha(spec, pass_channels(spec, name.layer, name.pass));
        }
    return {};
}

}  // namespace

std::vector<int> matching_components(const ImageSpec& spec, const std::vector<int>& candidate,
                                     const std::vector<int>& beauty)
{
    std::vector<int> matched;
    for (int b : beauty) {
        std::string want = split_name(spec.channel_name(b)).component;
        auto it = std::find_if(candidate.begin(), candidate.end(), [&](int c) {
            return split_name(spec.channel_name(c)).component == want;
        });
        if (it == candidate.end())
            return {};
        matched.push_back(*it);
    }
    return matched;
}

std::vector<int> select_channels(const ImageSpec& spec, std::string_view selector, std::string_view file,
                                 std::string_view context)
{
    std::vector<int> indices;
    for (const std::string& token : Strutil::splits(selector, ",")) {
        int exact = spec.channelindex(token);
        if (exact >= 0) {
            indices.push_back(exact);
            continue;
        }
        size_t before = indices.size();
        for (int c = 0; c < spec.nchannels; ++c)
            if (Strutil::starts_with(spec.channel_name(c), token + "."))
                indices.push_back(c);
        if (indices.size() == before)
            throw RunError(format("{} : no channel or layer '{}' in {} (channels: {})", context, token,
                                  file, all_channel_names(spec)));
    }
    if (indices.empty())
        throw RunError(format("{} : no channels named in '{}'", context, selector));
    return indices;
}

Discovery discover_channels(const ImageSpec& spec, std::string_view beauty_selector, std::string_view file)
{
    Discovery found;
    found.beauty = beauty_selector.empty() ? find_beauty(spec)
                                           : select_channels(spec, beauty_selector, file, "--beauty");
    if (found.beauty.empty())
        throw RunError(format("no beauty channels found in {} (channels: {}); name them with --beauty CHANNELS",
                              file, all_channel_names(spec)));
    found.layer = split_name(spec.channel_name(found.beauty.front())).layer;
    for (const RoleInfo& info : role_table()) {
        for (const char* pass : info.pass_names) {
            std::vector<int> indices = pass_channels(spec, found.layer, pass);
            if (info.like_beauty)
                indices = matching_components(spec, indices, found.beauty);
            if (!indices.empty() && channel_count_ok(info, int(indices.size()), int(found.beauty.size()))) {
                found.roles[info.role] = indices;
                break;
            }
        }
    }
    const int hashes = find_cryptomatte_object_ids(spec, found.layer);
    if (!found.roles.count(Role::id) && hashes >= 0)
        found.roles[Role::id] = { hashes };
    return found;
}

ImageBuf extract_channels(const ImageBuf& src, const std::vector<int>& indices)
{
    const ImageSpec& from = src.spec();
    const bool gather = from.format == OIIO::TypeDesc::FLOAT && from.channelformats.empty()
                        && src.localpixels() && from.depth == 1;
    if (!gather) {
        ImageBuf out;
        if (!OIIO::ImageBufAlgo::channels(out, src, int(indices.size()), indices))
            throw RunError(format("cannot extract channels: {}", one_line(out.geterror())));
        return out;
    }
    ImageBuf out(extracted_spec(from, indices), OIIO::InitializePixels::No);
    const int n = int(indices.size()), width = from.width;
    const size_t step = size_t(src.pixel_stride()) / sizeof(float);
    OIIO::ImageBufAlgo::parallel_image(src.roi(), [&](OIIO::ROI rows) {
        for (int y = rows.ybegin; y < rows.yend; ++y) {
            const float* in = static_cast<const float*>(src.pixeladdr(from.x, y, from.z));
            float* o        = static_cast<float*>(out.pixeladdr(from.x, y, from.z));
            for (int x = 0; x < width; ++x, in += step, o += n)
                for (int c = 0; c < n; ++c)
                    o[c] = in[indices[size_t(c)]];
        }
    });
    return out;
}

}  // namespace mcdtool
