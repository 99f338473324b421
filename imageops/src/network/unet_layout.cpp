// unet_layout.cpp: reads a UNet's shape from its weights' names and shapes
// (unet_layout.h), and the figures that follow from it.
#include "network/unet_layout.h"

#include <algorithm>
#include <cctype>
#include <tuple>

namespace mcdenoise {

namespace {

/// A convolution's name parsed: "enc_conv5a" is encoder, digit 5, suffix "a".
struct ConvName {
    bool encoder = false;
    int digit = 0;
    std::string suffix;
    std::string name;
};

/// Parses "enc_conv<digit><letters>" or "dec_conv<digit><letters>".
bool parse_conv_name(const std::string& name, ConvName& parsed)
{
    const std::string enc = "enc_conv", dec = "dec_conv";
    size_t prefix = 0;
    if (name.compare(0, enc.size(), enc) == 0) {
        parsed.encoder = true;
        prefix         = enc.size();
    } else if (name.compare(0, dec.size(), dec) == 0) {
        parsed.encoder = false;
        prefix         = dec.size();
    } else {
        return false;
    }
    if (name.size() <= prefix || !std::isdigit(static_cast<unsigned char>(name[prefix])))
        return false;
    parsed.digit  = name[prefix] - '0';
    parsed.suffix = name.substr(prefix + 1);
    for (char c : parsed.suffix)
        if (!std::islower(static_cast<unsigned char>(c)))
            return false;
    parsed.name = name;
    return true;
}

/// The resolution level of a convolution: OIDN names encoder and decoder
/// convolutions by the level they follow the pooling of, 0 and 1 both
/// being full resolution.
int conv_level(const ConvName& name) { return std::max(0, name.digit - 1); }

/// Runs before `b` on the same level: encoders count up (enc_conv0,
/// enc_conv1, ...), decoders count down (dec_conv1a, dec_conv1b,
/// dec_conv0), letters in order.
bool runs_before(const ConvName& a, const ConvName& b)
{
    if (a.encoder)
        return std::tie(a.digit, a.suffix) < std::tie(b.digit, b.suffix);
    return std::make_tuple(-a.digit, a.suffix) < std::make_tuple(-b.digit, b.suffix);
}

/// Collects the weight and bias of `name` into `conv`, checking their shapes.
bool read_conv(const TensorMap& tensors, const std::string& name, const std::string& source,
               UNetConv& conv, std::string& error)
{
    const auto weight = tensors.find(name + ".weight");
    const auto bias   = tensors.find(name + ".bias");
    if (weight == tensors.end() || bias == tensors.end()) {
        error = source + ": convolution '" + name + "' lacks its "
                + (weight == tensors.end() ? "weight" : "bias");
        return false;
    }
    const Tensor& w = weight->second;
    const Tensor& b = bias->second;
    if (w.layout != "oihw" || w.dims[2] != 3 || w.dims[3] != 3) {
        error = source + ": '" + name + ".weight' is not a 3x3 convolution's (oihw)";
        return false;
    }
    if (b.layout != "x" || b.dims[0] != w.dims[0]) {
        error = source + ": '" + name + ".bias' does not have one value per output channel ("
                + std::to_string(w.dims[0]) + ")";
        return false;
    }
    conv.name         = name;
    conv.out_channels = w.dims[0];
    conv.in_channels  = w.dims[1];
    conv.weight       = &w.values;
    conv.bias         = &b.values;
    return true;
}

/// Sorts the convolutions named in `tensors` into levels; false on an
/// unknown tensor name.
bool collect_names(const TensorMap& tensors, const std::string& source,
                   std::vector<std::vector<ConvName>>& encoders,
                   std::vector<std::vector<ConvName>>& decoders, std::string& error)
{
    encoders.assign(unet_levels, {});
    decoders.assign(unet_levels, {});
    for (const auto& entry : tensors) {
        const std::string& full = entry.first;
        const size_t dot        = full.rfind('.');
        ConvName parsed;
        const std::string kind = dot == std::string::npos ? "" : full.substr(dot + 1);
        if ((kind != "weight" && kind != "bias") || !parse_conv_name(full.substr(0, dot), parsed)
            || conv_level(parsed) >= unet_levels) {
            error = source + ": tensor '" + full + "' is not part of an OIDN UNet";
            return false;
        }
        if (kind == "bias" && !tensors.count(full.substr(0, dot) + ".weight")) {
            error = source + ": '" + full + "' has no weight";
            return false;
        }
        if (kind != "weight")
            continue;
        auto& level = (parsed.encoder ? encoders : decoders)[conv_level(parsed)];
        level.push_back(parsed);
    }
    for (auto* side : { &encoders, &decoders })
        for (auto& level : *side)
            std::sort(level.begin(), level.end(), runs_before);
    return true;
}

/// Checks that every convolution takes the channels its input has.
bool check_chain(const UNetLayout& layout, const std::string& source, std::string& error)
{
    auto expect = [&](const UNetConv& conv, int channels) {
        if (conv.in_channels == channels)
            return true;
        error = source + ": '" + conv.name + "' takes " + std::to_string(conv.in_channels)
                + " channels where the network has " + std::to_string(channels);
        return false;
    };
    for (int level = 0; level < unet_levels; ++level) {
        int channels = layout.level_input_channels(level);
        for (const UNetConv& conv : layout.levels[level].encoder) {
            if (!expect(conv, channels))
                return false;
            channels = conv.out_channels;
        }
    }
    for (int level = unet_levels - 2; level >= 0; --level) {
        int channels = layout.upsampled_channels(level) + layout.level_input_channels(level);
        for (const UNetConv& conv : layout.levels[level].decoder) {
            if (!expect(conv, channels))
                return false;
            channels = conv.out_channels;
        }
    }
    if (layout.levels[0].decoder.back().out_channels != unet_output_channels) {
        error = source + ": the last convolution gives "
                + std::to_string(layout.levels[0].decoder.back().out_channels)
                + " channels, not 3";
        return false;
    }
    return true;
}

}  // namespace

int UNetLayout::level_input_channels(int level) const
{
    return level == 0 ? input_channels : levels[level - 1].encoder.back().out_channels;
}

int UNetLayout::upsampled_channels(int level) const
{
    const UNetLevel& below = levels[level + 1];
    return (below.decoder.empty() ? below.encoder : below.decoder).back().out_channels;
}

double UNetLayout::flops_per_pixel() const
{
    double flops = 0;
    for (int level = 0; level < int(levels.size()); ++level)
        for (const auto* side : { &levels[level].encoder, &levels[level].decoder })
            for (const UNetConv& conv : *side)
                flops += 2.0 * 9.0 * conv.in_channels * conv.out_channels / double(1 << (2 * level));
    return flops;
}

int UNetLayout::receptive_field() const
{
    // A 3x3 convolution at level L widens the field by 2 * 2^L pixels, a
    // 2x2 pooling of level L by 2^L.
    int field = 1;
    for (int level = 0; level < int(levels.size()); ++level) {
        const int convs = int(levels[level].encoder.size() + levels[level].decoder.size());
        field += convs * 2 * (1 << level);
        if (level + 1 < int(levels.size()))
            field += 1 << level;
    }
    return field;
}

int UNetLayout::tile_overlap() const
{
    const int half = (receptive_field() + 1) / 2;
    return (half + unet_alignment - 1) / unet_alignment * unet_alignment;
}

std::vector<const UNetConv*> UNetLayout::convolutions() const
{
    std::vector<const UNetConv*> order;
    for (const UNetLevel& level : levels)
        for (const UNetConv& conv : level.encoder)
            order.push_back(&conv);
    for (int level = int(levels.size()) - 2; level >= 0; --level)
        for (const UNetConv& conv : levels[level].decoder)
            order.push_back(&conv);
    return order;
}

bool read_unet_layout(const TensorMap& tensors, const std::string& source, UNetLayout& layout,
                      std::string& error)
{
    layout = UNetLayout();
    std::vector<std::vector<ConvName>> encoders, decoders;
    if (!collect_names(tensors, source, encoders, decoders, error))
        return false;
    layout.levels.resize(unet_levels);
    for (int level = 0; level < unet_levels; ++level) {
        const bool needs_decoder = level + 1 < unet_levels;
        if (encoders[level].empty() || needs_decoder == decoders[level].empty()) {
            error = source + ": level " + std::to_string(level) + " of the UNet has "
                    + (encoders[level].empty() ? "no encoder convolution"
                                               : "a decoder where none belongs or none where one does");
            return false;
        }
        for (const auto* side : { &encoders[level], &decoders[level] })
            for (const ConvName& name : *side) {
                UNetConv conv;
                if (!read_conv(tensors, name.name, source, conv, error))
                    return false;
                (name.encoder ? layout.levels[level].encoder : layout.levels[level].decoder)
                    .push_back(conv);
            }
    }
    layout.input_channels = layout.levels[0].encoder.front().in_channels;
    if (!check_chain(layout, source, error)) {
        layout = UNetLayout();
        return false;
    }
    return true;
}

}  // namespace mcdenoise
