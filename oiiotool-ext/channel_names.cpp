// channel_names.cpp: channel-name parsing and listing, and the spec of a
// subset of channels.
#include "channel_names.h"

#include <OpenImageIO/strutil.h>

#include <algorithm>

namespace mcdtool {

namespace Strutil = OIIO::Strutil;

namespace {

/// Bare channel names that belong to the beauty pass, not a pass of their own.
const std::vector<std::string> bare_beauty = { "R", "G", "B", "A", "Y" };

}  // namespace

ChannelName split_name(const std::string& name)
{
    size_t dot = name.rfind('.');
    if (dot == std::string::npos) {
        bool beauty = std::find(bare_beauty.begin(), bare_beauty.end(), name) != bare_beauty.end();
        return { "", beauty ? "" : name, name };
    }
    std::string rest = name.substr(0, dot);
    std::string component = name.substr(dot + 1);
    size_t dot2 = rest.rfind('.');
    if (dot2 == std::string::npos)
        return { "", rest, component };
    return { rest.substr(0, dot2), rest.substr(dot2 + 1), component };
}

ImageSpec extracted_spec(const ImageSpec& from, const std::vector<int>& indices)
{
    ImageSpec spec = from;
    spec.set_format(OIIO::TypeDesc::FLOAT);
    spec.nchannels = int(indices.size());
    spec.channelnames.clear();
    spec.alpha_channel = spec.z_channel = -1;
    for (int c : indices) {
        if (c == from.alpha_channel)
            spec.alpha_channel = int(spec.channelnames.size());
        if (c == from.z_channel)
            spec.z_channel = int(spec.channelnames.size());
        spec.channelnames.push_back(from.channel_name(c));
    }
    return spec;
}

std::string channel_names(const ImageSpec& spec, const std::vector<int>& indices)
{
    std::vector<std::string> names;
    for (int c : indices)
        names.push_back(spec.channel_name(c));
    return Strutil::join(names, ",");
}

std::string all_channel_names(const ImageSpec& spec)
{
    std::vector<int> all(size_t(std::max(spec.nchannels, 0)));
    for (size_t c = 0; c < all.size(); ++c)
        all[c] = int(c);
    return channel_names(spec, all);
}

}  // namespace mcdtool
