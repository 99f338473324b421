// cryptomatte.cpp: Cryptomatte layer names from metadata or defaults, the
// rank-0 object id channel, and hashes turned into whole-number ids.
#include "cryptomatte.h"

#include "channel_names.h"

#include <OpenImageIO/strutil.h>

#include <cctype>
#include <cstdint>
#include <cstring>
#include <vector>

namespace mcdtool {

namespace Strutil = OIIO::Strutil;

namespace {

/// The Cryptomatte layer names of `spec`: the values of its
/// `cryptomatte/<key>/name` attributes (none when the metadata was
/// stripped).
std::vector<std::string> layer_names(const OIIO::ImageSpec& spec)
{
    std::vector<std::string> names;
    for (const OIIO::ParamValue& p : spec.extra_attribs) {
        const std::string key = p.name().string();
        if (Strutil::istarts_with(key, "cryptomatte/") && Strutil::iends_with(key, "/name"))
            names.push_back(p.get_string());
    }
    return names;
}

/// True if `name` is `<layer>NN.<component>` for a Cryptomatte layer named
/// `layer` (or, with no metadata, a default one), NN two digits.
bool is_rank_channel(const std::vector<std::string>& layers, const std::string& name,
                     const char* component)
{
    const std::string suffix = std::string(".") + component;
    if (name.size() < suffix.size() + 3 || !Strutil::ends_with(name, suffix))
        return false;
    const std::string rank  = name.substr(name.size() - suffix.size() - 2, 2);
    const std::string layer = name.substr(0, name.size() - suffix.size() - 2);
    if (!std::isdigit(static_cast<unsigned char>(rank[0]))
        || !std::isdigit(static_cast<unsigned char>(rank[1])))
        return false;
    if (layers.empty()) {
        const std::string last = layer.substr(layer.rfind('.') + 1);
        return Strutil::iequals(last, "CryptoObject") || Strutil::iequals(last, "crypto_object");
    }
    for (const std::string& l : layers)
        if (l == layer)
            return true;
    return false;
}

}  // namespace

bool is_cryptomatte_id_channel(const OIIO::ImageSpec& spec, int c)
{
    const std::vector<std::string> layers = layer_names(spec);
    const std::string name                = spec.channel_name(c);
    return is_rank_channel(layers, name, "R") || is_rank_channel(layers, name, "B");
}

int find_cryptomatte_object_ids(const OIIO::ImageSpec& spec, const std::string& layer)
{
    const std::vector<std::string> layers = layer_names(spec);
    for (int c = 0; c < spec.nchannels; ++c) {
        const ChannelName name = split_name(spec.channel_name(c));  // pass "<name>00"
        if (name.layer == layer && name.component == "R" && Strutil::ends_with(name.pass, "00")
            && Strutil::iends_with(name.pass.substr(0, name.pass.size() - 2), "object")
            && is_rank_channel(layers, spec.channel_name(c), "R"))
            return c;
    }
    return -1;
}

OIIO::ImageBuf cryptomatte_ids(const OIIO::ImageBuf& src, int c)
{
    OIIO::ImageSpec spec = extracted_spec(src.spec(), { c });
    spec.set_format(OIIO::TypeUInt32);
    const size_t n = size_t(spec.image_pixels());
    std::vector<float> values(n);
    std::vector<uint32_t> ids(n);
    OIIO::ROI channel = src.roi();
    channel.chbegin   = c;
    channel.chend     = c + 1;
    src.get_pixels(channel, OIIO::TypeFloat, values.data());
    std::memcpy(ids.data(), values.data(), n * sizeof(float));
    OIIO::ImageBuf out(spec, OIIO::InitializePixels::No);
    out.set_pixels(out.roi(), OIIO::TypeUInt32, ids.data());
    return out;
}

}  // namespace mcdtool
