// light_passes.cpp: finding the light passes by name, extracting them, and
// rebuilding a Cycles-style beauty from them.
#include "light_passes.h"

#include "error.h"

#include <mcdenoise/metrics.h>

#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/strutil.h>

#include <algorithm>
#include <cstdio>

namespace mcdtool {

using OIIO::Strutil::fmt::format;
namespace Strutil = OIIO::Strutil;
namespace IBA     = OIIO::ImageBufAlgo;

namespace {

/// Cycles' lobes: their <Lobe>Dir and <Lobe>Ind passes are irradiance, the
/// light divided by the <Lobe>Col pass.
const std::vector<std::string> cycles_lobes = { "Diff", "Gloss", "Trans" };
/// The light passes "auto" takes, by renderer: the lists of exact pass
/// names that each add up to the beauty, and prefixes of light-group
/// passes (<prefix><group>), every group of every prefix adding up to the
/// beauty together.
struct KnownPasses {
    const char* renderer;
    std::vector<std::vector<std::string>> sums;
    std::vector<std::string> group_prefixes;
};
const std::vector<KnownPasses> known_passes = {
    { "Cycles, testrender",
      { { "DiffDir", "DiffInd", "GlossDir", "GlossInd", "TransDir", "TransInd", "VolumeDir",
          "VolumeInd", "Emit", "Env" } },
      { "Combined_" } },
    { "Arnold",
      { { "direct", "indirect", "emission", "background" },
        { "diffuse", "specular", "coat", "transmission", "sss", "volume", "sheen" },
        { "diffuse_direct", "diffuse_indirect", "specular_direct", "specular_indirect",
          "coat_direct", "coat_indirect", "transmission_direct", "transmission_indirect",
          "sss_direct", "sss_indirect", "volume_direct", "volume_indirect", "sheen_direct",
          "sheen_indirect" } },
      { "RGBA_" } },
    { "RenderMan",
      { { "directDiffuse", "indirectDiffuse", "directSpecular", "indirectSpecular", "subsurface",
          "transmissive", "emissive" } },
      { "directDiffuse_", "indirectDiffuse_", "directSpecular_", "indirectSpecular_",
        "subsurface_", "transmissive_", "emissive_" } },
};

/// The rebuild `pass` is a term of: the index of its list of names or of
/// its renderer's group prefixes, counted over `known_passes` in order;
/// -1 if "auto" does not know it.
int sum_of(const std::string& pass)
{
    int index = 0;
    for (const KnownPasses& known : known_passes) {
        for (const std::vector<std::string>& names : known.sums) {
            if (std::find(names.begin(), names.end(), pass) != names.end())
                return index;
            ++index;
        }
        for (const std::string& prefix : known.group_prefixes)
            if (pass.size() > prefix.size() && Strutil::starts_with(pass, prefix))
                return index;
        ++index;
    }
    return -1;
}

/// True if `pass` is a Cycles irradiance pass (<Lobe>Dir, <Lobe>Ind).
bool is_cycles_light(const std::string& pass)
{
    for (const std::string& lobe : cycles_lobes)
        if (pass == lobe + "Dir" || pass == lobe + "Ind")
            return true;
    return false;
}

/// True if `pass` is a colour pass (<Lobe>Col).
bool is_cycles_colour(const std::string& pass)
{
    return std::any_of(cycles_lobes.begin(), cycles_lobes.end(),
                       [&](const std::string& lobe) { return pass == lobe + "Col"; });
}

/// True if "auto" takes `pass`.
bool is_known_light(const std::string& pass) { return sum_of(pass) >= 0; }

/// The pass names of view layer `layer` in file order, each once.
std::vector<std::string> layer_passes(const ImageSpec& spec, const std::string& layer)
{
    std::vector<std::string> passes;
    for (int c = 0; c < spec.nchannels; ++c) {
        const ChannelName name = split_name(spec.channel_name(c));
        if (name.layer == layer && !name.pass.empty()
            && std::find(passes.begin(), passes.end(), name.pass) == passes.end())
            passes.push_back(name.pass);
    }
    return passes;
}

/// True if any of `channels` is the beauty's or a discovered guide's.
bool is_taken(const std::vector<int>& channels, const Discovery& found)
{
    const auto overlaps = [&](const std::vector<int>& other) {
        return std::any_of(channels.begin(), channels.end(), [&](int c) {
            return std::find(other.begin(), other.end(), c) != other.end();
        });
    };
    if (overlaps(found.beauty))
        return true;
    return std::any_of(found.roles.begin(), found.roles.end(),
                       [&](const auto& role) { return overlaps(role.second); });
}

/// The beauty's colour channels (the first three).
std::vector<int> colour_of(const Discovery& found)
{
    return { found.beauty.begin(),
             found.beauty.begin() + std::ptrdiff_t(std::min<size_t>(3, found.beauty.size())) };
}

/// Pass `pass` as a LightPass; no channels if it lacks a beauty colour.
LightPass light_pass(const ImageSpec& spec, const std::string& pass, const Discovery& found)
{
    LightPass light { pass, matching_components(spec, pass_channels(spec, found.layer, pass),
                                                colour_of(found)),
                      {}, sum_of(pass) };
    if (is_cycles_light(pass))
        light.colour = matching_components(
            spec, pass_channels(spec, found.layer, pass.substr(0, pass.size() - 3) + "Col"),
            colour_of(found));
    return light;
}

/// "--aovs : ..." for a listed pass that cannot be denoised as light.
void check_listed(const ImageSpec& spec, const std::string& name, const LightPass& pass,
                  const Discovery& found, std::string_view file)
{
    const std::vector<int> all = pass_channels(spec, found.layer, name);
    if (all.empty())
        throw RunError(format("--aovs : no pass '{}' beside the beauty in {} (channels: {})", name,
                              file, all_channel_names(spec)));
    if (is_cycles_colour(name) || is_taken(all, found))
        throw RunError(format("--aovs : '{}' in {} is {}, not a light pass; it is never changed",
                              name, file,
                              is_cycles_colour(name) ? "a colour pass" : "the beauty or a guide"));
    if (pass.channels.empty())
        throw RunError(format("--aovs : pass '{}' in {} lacks the beauty's channels {}", name, file,
                              channel_names(spec, colour_of(found))));
}

/// The rebuild the passes with a colour pass are terms of (Cycles'), or
/// -1 when none has one.
int coloured_sum(const std::vector<LightPass>& passes)
{
    for (const LightPass& pass : passes)
        if (!pass.colour.empty())
            return pass.sum;
    return -1;
}

}  // namespace

std::vector<std::pair<std::string, std::string>> known_light_passes()
{
    std::vector<std::pair<std::string, std::string>> rows;
    for (const KnownPasses& known : known_passes) {
        std::vector<std::string> names;
        for (const std::vector<std::string>& sum : known.sums)
            names.insert(names.end(), sum.begin(), sum.end());
        for (const std::string& prefix : known.group_prefixes)
            names.push_back(prefix + "<group>");
        rows.emplace_back(known.renderer, Strutil::join(names, ", "));
    }
    return rows;
}

std::vector<std::pair<std::string, std::string>> known_rebuilds()
{
    std::vector<std::pair<std::string, std::string>> rows;
    for (const KnownPasses& known : known_passes) {
        for (const std::vector<std::string>& sum : known.sums) {
            std::vector<std::string> terms;
            for (const std::string& pass : sum)  // Cycles' irradiance times its colour pass
                terms.push_back(is_cycles_light(pass) ? pass.substr(0, pass.size() - 3) + "Col x " + pass
                                                      : pass);
            rows.emplace_back(known.renderer, Strutil::join(terms, " + "));
        }
        std::vector<std::string> groups;
        for (const std::string& prefix : known.group_prefixes)
            groups.push_back(prefix + "<group>");
        rows.emplace_back(known.renderer, Strutil::join(groups, " + "));
    }
    return rows;
}

std::vector<LightPass> find_light_passes(const ImageSpec& spec, std::string_view request,
                                         const Discovery& found, std::string_view file)
{
    std::vector<LightPass> passes;
    if (request == "auto") {
        for (const std::string& name : layer_passes(spec, found.layer)) {
            LightPass pass = light_pass(spec, name, found);
            if (is_known_light(name) && !pass.channels.empty()
                && !is_taken(pass.channels, found))
                passes.push_back(pass);
        }
        return passes;
    }
    for (const std::string& name : Strutil::splits(request, ",")) {
        LightPass pass = light_pass(spec, name, found);
        check_listed(spec, name, pass, found, file);
        passes.push_back(pass);
    }
    return passes;
}

LightLayers load_light_layers(const ImageBuf& input, std::vector<LightPass> passes,
                              const ImageBuf& beauty, std::string_view file)
{
    LightLayers layers;
    layers.passes = std::move(passes);
    bool coloured = false;
    for (const LightPass& pass : layers.passes) {
        layers.images.push_back(extract_channels(input, pass.channels));
        layers.colours.push_back(pass.colour.empty() ? ImageBuf()
                                                     : extract_channels(input, pass.colour));
        coloured |= !pass.colour.empty();
    }
    if (!coloured)
        return layers;
    const double error = mcdenoise::rel_mse(rebuild_beauty(layers, beauty), beauty);
    layers.rebuild     = error <= rebuild_relmse_tolerance;
    if (!layers.rebuild)
        std::fprintf(stderr,
                     "mcdtool WARNING: --aovs : the light passes of %s do not add up to the beauty "
                     "(relMSE %.3g): the passes are denoised, the beauty on its own\n",
                     std::string(file).c_str(), error);
    return layers;
}

ImageBuf rebuild_beauty(const LightLayers& layers, const ImageBuf& beauty)
{
    const int nc = std::min(3, beauty.nchannels());
    ImageBuf sum = IBA::zero(OIIO::ROI(beauty.roi().xbegin, beauty.roi().xend,
                                       beauty.roi().ybegin, beauty.roi().yend, 0, 1, 0, nc));
    const int rebuilt = coloured_sum(layers.passes);
    std::vector<bool> done(layers.passes.size(), false);
    for (size_t i = 0; i < layers.passes.size(); ++i) {
        if (done[i] || layers.passes[i].sum != rebuilt)
            continue;
        ImageBuf term = layers.images[i];
        // the other pass of the same colour (Dir with Ind) goes in first
        for (size_t j = i + 1; j < layers.passes.size(); ++j)
            if (!done[j] && !layers.passes[i].colour.empty()
                && layers.passes[j].colour == layers.passes[i].colour) {
                term    = IBA::add(term, layers.images[j]);
                done[j] = true;
            }
        if (!layers.passes[i].colour.empty())
            term = IBA::mul(term, layers.colours[i]);
        sum = IBA::add(sum, term);
    }
    ImageBuf out = beauty;
    if (!IBA::paste(out, out.roi().xbegin, out.roi().ybegin, 0, 0, sum))
        throw RunError(format("--aovs : cannot rebuild the beauty: {}", one_line(out.geterror())));
    return out;
}

std::vector<int> written_channels(const std::vector<int>& beauty, const LightLayers& layers)
{
    std::vector<int> channels = beauty;
    for (const LightPass& pass : layers.passes)
        channels.insert(channels.end(), pass.channels.begin(), pass.channels.end());
    return channels;
}

ImageBuf written_pixels(const ImageBuf& beauty, const LightLayers& layers)
{
    ImageBuf all = beauty;
    for (const ImageBuf& image : layers.images)
        all = IBA::channel_append(all, image);
    return all;
}

}  // namespace mcdtool
