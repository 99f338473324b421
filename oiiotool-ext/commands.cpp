// commands.cpp: the rows of the command table, one library call each.
#include "commands.h"

#include <mcdenoise/mcdenoise.h>

#include <OpenImageIO/strutil.h>

namespace mcdtool {

using OIIO::Strutil::fmt::format;

namespace {

/// The guide for `role` in `guides`, or nullptr.
const ImageBuf* present(const GuideImages& guides, Role role)
{
    const auto found = guides.images.find(role);
    return found == guides.images.end() ? nullptr : &found->second;
}

}  // namespace

int Call::integer(size_t i) const { return OIIO::Strutil::stoi(values.at(i)); }

float Call::number(size_t i) const { return OIIO::Strutil::stof(values.at(i)); }

const ImageBuf& Call::guide(Role role) const { return guides.images.at(role); }

const ImageBuf* Call::optional_guide(Role role) const { return present(guides, role); }

std::string Call::modifier(const char* key) const
{
    if (modifiers) {
        const auto typed = modifiers->find(key);
        if (typed != modifiers->end())
            return typed->second;
    }
    for (const Modifier& m : command->modifiers)
        if (std::string_view(m.key) == key)
            return m.values.front();
    return "";
}

mcdenoise::Guides library_guides(const GuideImages& images)
{
    mcdenoise::Guides guides;
    for (const RoleInfo& info : role_table())
        for (const mcdenoise::GuideField& field : mcdenoise::guide_fields)
            if (std::string_view(field.name) == info.argument)
                guides.*field.member = present(images, info.role);
    return guides;
}

namespace {

/// The window-side parameter every window filter takes.
const Param size_param = { "SIZE", ParamType::integer, "odd window side, 1..255", 1, mcdenoise::max_window_size,
                           true };
/// The parameters of the depth-of-field filter.
const Param levels_param = { "LEVELS", ParamType::integer, "number of depth levels, >= 1", 1 };
const Param focus_param = { "FOCUS", ParamType::integer, "the level in focus, 0..LEVELS-1 (0 is nearest)", 0 };
const Param near_param = { "NEAR", ParamType::number, "depth mapped to the first level (nearer clamps)" };
const Param far_param = { "FAR", ParamType::number, "depth mapped past the last level (farther clamps)" };
/// The parameters of the feature-guided filters.
const Param iterations_param = { "ITERATIONS", ParamType::integer, "a-trous passes, 1..10 (step 2^i)", 1,
                                 mcdenoise::max_atrous_iterations };
const Param factor_param = { "FACTOR", ParamType::number, "times the 75th-percentile neighbour a pixel may be, >= 1",
                             1 };
const Param search_param = { "SEARCH_RADIUS", ParamType::integer, "search window radius, 0..127 (patch radius 1)",
                             0, mcdenoise::max_nlmeans_search_radius };

/// The roles whose guides fill the `mcdenoise::Guides` fields of `guides`, in the
/// role table's order.
std::vector<Role> roles_of(mcdenoise::GuideMask guides)
{
    std::vector<Role> roles;
    for (const RoleInfo& info : role_table())
        if (guides & mcdenoise::guide_bit(info.argument))
            roles.push_back(info.role);
    return roles;
}

/// The present guides of `call` in the library's form.
mcdenoise::Guides feature_guides(const Call& call) { return library_guides(call.guides); }

/// `denoise` of the beauty with the light passes of `call`, which are
/// replaced by their denoised forms; each pass a term of its renderer's
/// rebuild of the beauty (`LightPass::sum`), times its colour pass if any.
bool denoise_layers(const Call& call)
{
    std::vector<const ImageBuf*> layers;
    std::vector<mcdenoise::LayerTerm> terms;
    for (size_t i = 0; i < call.layers->images.size(); ++i) {
        const ImageBuf& colour = call.layers->colours[i];
        layers.push_back(&call.layers->images[i]);
        terms.push_back({ call.layers->passes[i].sum, colour.initialized() ? &colour : nullptr });
    }
    std::vector<ImageBuf> denoised;
    if (!mcdenoise::denoise_layers(call.dst, denoised, call.beauty, layers, feature_guides(call),
                                   terms, {}, call.nthreads))
        return false;
    call.layers->images = std::move(denoised);
    return true;
}

/// The preparation of `frame` for the cross-frame denoise, made now unless
/// its window holds it.
const mcdenoise::PreparedFrame& prepared(const WindowFrame& frame, int nthreads)
{
    if (!frame.prepared->data && frame.prepared->error.empty())
        *frame.prepared = mcdenoise::prepare_frame({ frame.beauty, library_guides(*frame.guides) }, nthreads);
    return *frame.prepared;
}

/// The network's options as the modifiers of `c` say; with -v each
/// phase's time.
mcdenoise::NetworkOptions network_options(const Call& c)
{
    mcdenoise::NetworkOptions options;
    for (const mcdenoise::NetworkQualityName& q : mcdenoise::network_quality_names)
        if (c.modifier("quality") == q.name)
            options.quality = q.quality;
    options.prefilter_guides = c.modifier("prefilter") == "1";
    options.memory_limit     = c.memory_limit;
    options.on_progress      = c.progress;
    if (c.verbose)
        options.on_phase = [](const std::string& phase, double seconds) {
            std::printf("mcdtool: --denoise   %s  %.3f s\n", phase.c_str(), seconds);
        };
    return options;
}

/// The network result of `frame` and its preparation, made now unless its
/// window holds them (the preparation shared with the NL-means' cross-frame
/// form).
const mcdenoise::NetworkFrame& network_frame(const WindowFrame& frame, const Call& c)
{
    mcdenoise::NetworkFrame& n = *frame.network;
    if (n.denoised || !n.error.empty())
        return n;
    n.prepared = prepared(frame, c.nthreads);
    if (!n.prepared.data) {
        n.error = n.prepared.error;
        return n;
    }
    mcdenoise::Guides guides;
    guides.albedo = present(*frame.guides, Role::albedo);
    guides.normal = present(*frame.guides, Role::normal);
    auto denoised = std::make_shared<ImageBuf>();
    if (mcdenoise::denoise_network(*denoised, *frame.beauty, guides, network_options(c), {}, c.nthreads))
        n.denoised = std::move(denoised);
    else
        n.error = denoised->geterror();
    return n;
}

/// --denoise on the network (denoise_network.h): of the frame alone, or,
/// with --temporal, each frame's result (made once in its window)
/// accumulated across the frames that show the same thing.
bool network_denoise(const Call& c)
{
    if (c.neighbours && !c.neighbours->empty()) {
        std::vector<mcdenoise::NetworkFrame> neighbours;
        std::vector<int> offsets;
        for (const WindowFrame& n : *c.neighbours) {
            neighbours.push_back(network_frame(n, c));
            offsets.push_back(n.offset);
        }
        return mcdenoise::denoise_network(c.dst, network_frame(*c.centre, c), neighbours, offsets, {},
                                          c.nthreads);
    }
    mcdenoise::Guides guides;
    guides.albedo = c.optional_guide(Role::albedo);
    guides.normal = c.optional_guide(Role::normal);
    return mcdenoise::denoise_network(c.dst, c.beauty, guides, network_options(c), {}, c.nthreads);
}

/// The one-line note that --denoise runs the NL-means operator where the
/// network has no mode yet (light passes), printed once a run.
void note_network_fallback(const char* what)
{
    static bool noted = false;
    if (noted)
        return;
    noted = true;
    std::fprintf(stderr,
                 "mcdtool: note: --denoise with %s runs the NL-means operator (the network has no "
                 "such mode yet); --denoise:method=nlm chooses it explicitly\n",
                 what);
}

/// --denoise: the network (of the frame alone or across frames) unless
/// `method=nlm`, or light passes ask for the NL-means operator; then the
/// cross-frame form when the call has neighbours, of the frames as their
/// window prepared them (with no neighbour on disk the single-frame form,
/// which that equals bit for bit).
bool denoise_call(const Call& c)
{
    const bool layered = c.layers && !c.layers->images.empty();
    if (c.modifier("method") == "network") {
        if (!layered)
            return network_denoise(c);
        note_network_fallback("--aovs");
    }
    if (layered)
        return denoise_layers(c);
    if (!c.neighbours || c.neighbours->empty())
        return mcdenoise::denoise(c.dst, c.beauty, feature_guides(c), {}, c.nthreads);
    std::vector<mcdenoise::PreparedFrame> neighbours;
    std::vector<int> offsets;
    for (const WindowFrame& n : *c.neighbours) {
        neighbours.push_back(prepared(n, c.nthreads));
        offsets.push_back(n.offset);
    }
    return mcdenoise::denoise(c.dst, prepared(*c.centre, c.nthreads), neighbours, offsets, {}, c.nthreads);
}

}  // namespace

const std::vector<Command>& command_table()
{
    static const std::vector<Command> table = {
        { "mean", "mean", "simple.h", { size_param }, {},
          "Box mean of the SIZE x SIZE window (finite values only).",
          "mcdtool render.exr --mean 5 -o clean.exr",
          [](const Call& c) { return mcdenoise::mean(c.dst, c.beauty, c.integer(0), {}, c.nthreads); } },
        { "median", "median", "simple.h", { size_param }, {},
          "Per-channel median of the SIZE x SIZE window.",
          "mcdtool render.exr --median 7 --gaussian 3 -o clean.exr",
          [](const Call& c) { return mcdenoise::median(c.dst, c.beauty, c.integer(0), {}, c.nthreads); } },
        { "gaussian", "gaussian", "simple.h", { size_param }, {},
          "Binomial (Pascal's triangle) weighted mean of the SIZE x SIZE window.",
          "mcdtool render.exr --gaussian 3 -o clean.exr",
          [](const Call& c) { return mcdenoise::gaussian(c.dst, c.beauty, c.integer(0), {}, c.nthreads); } },
        { "object-mean", "object_mean", "object.h", { size_param }, { Role::id },
          "Mean over the window's pixels that share the center's object id.",
          "mcdtool render.exr --object-mean 5 -o clean.exr",
          [](const Call& c) {
              return mcdenoise::object_mean(c.dst, c.beauty, c.guide(Role::id), c.integer(0), {}, c.nthreads);
          } },
        { "object-median", "object_median", "object.h", { size_param }, { Role::id },
          "Median over the window's pixels that share the center's object id (the report's best chain "
          "is --object-median 7 --gaussian 3).",
          "mcdtool render.exr --object-median 7 --gaussian 3 -o clean.exr",
          [](const Call& c) {
              return mcdenoise::object_median(c.dst, c.beauty, c.guide(Role::id), c.integer(0), {}, c.nthreads);
          } },
        { "object-gaussian", "object_gaussian", "object.h", { size_param }, { Role::id },
          "Binomial-weighted mean over the window's pixels that share the center's object id.",
          "mcdtool render.exr --object-gaussian 5 -o clean.exr",
          [](const Call& c) {
              return mcdenoise::object_gaussian(c.dst, c.beauty, c.guide(Role::id), c.integer(0), {},
                                                c.nthreads);
          } },
        { "brdf-mean", "brdf_mean", "brdf.h", { size_param }, { Role::id, Role::reflid },
          "Object mean that, at a specular pixel, also requires the same reflected object id.",
          "mcdtool render.exr --brdf-mean 5 -o clean.exr",
          [](const Call& c) {
              return mcdenoise::brdf_mean(c.dst, c.beauty, c.guide(Role::id), c.guide(Role::reflid),
                                          c.integer(0), {}, c.nthreads);
          } },
        { "brdf-median", "brdf_median", "brdf.h", { size_param }, { Role::id, Role::reflid },
          "Median over the pixels the BRDF rule makes viable (fireflies on mirrors).",
          "mcdtool render.exr --brdf-median 7 --brdf-gaussian 3 -o clean.exr",
          [](const Call& c) {
              return mcdenoise::brdf_median(c.dst, c.beauty, c.guide(Role::id), c.guide(Role::reflid),
                                            c.integer(0), {}, c.nthreads);
          } },
        { "brdf-gaussian", "brdf_gaussian", "brdf.h", { size_param }, { Role::id, Role::reflid },
          "Binomial-weighted mean over the pixels the BRDF rule makes viable.",
          "mcdtool render.exr --brdf-gaussian 3 -o clean.exr",
          [](const Call& c) {
              return mcdenoise::brdf_gaussian(c.dst, c.beauty, c.guide(Role::id), c.guide(Role::reflid),
                                              c.integer(0), {}, c.nthreads);
          } },
        { "normal-mean", "normal_mean", "normal.h", { size_param }, { Role::id, Role::normal },
          "Mean over the pixels of the center's object, weighted by max(0, dot) of the normals.",
          "mcdtool beauty.exr --aov id=ids.exr --aov normal=render.exr:N --normal-mean 5 -o out.exr",
          [](const Call& c) {
              return mcdenoise::normal_mean(c.dst, c.beauty, c.guide(Role::id), c.guide(Role::normal),
                                            c.integer(0), {}, c.nthreads);
          } },
        { "normal-gaussian", "normal_gaussian", "normal.h", { size_param }, { Role::id, Role::normal },
          "As --normal-mean, each weight also multiplied by the binomial spatial weight.",
          "mcdtool render.exr --normal-gaussian 5 -o clean.exr",
          [](const Call& c) {
              return mcdenoise::normal_gaussian(c.dst, c.beauty, c.guide(Role::id), c.guide(Role::normal),
                                                c.integer(0), {}, c.nthreads);
          } },
        { "dof", "dof", "dof.h", { levels_param, focus_param }, { Role::id, Role::depth },
          "Depth of field: the depth range (finite depths; >= 1e9, e.g. Cycles' background, is "
          "infinitely far) is cut into LEVELS levels; a pixel at level l gets the object mean of side "
          "1 + 2|l - FOCUS|.",
          "mcdtool render.exr --dof 10 0 -o out.exr",
          [](const Call& c) {
              return mcdenoise::dof(c.dst, c.beauty, c.guide(Role::id), c.guide(Role::depth), c.integer(0),
                                    c.integer(1), mcdenoise::dof_image_depth_range,
                                    mcdenoise::dof_image_depth_range, {}, c.nthreads);
          } },
        { "dof-range", "dof", "dof.h", { levels_param, focus_param, near_param, far_param }, { Role::id, Role::depth },
          "As --dof, with the levels spread over the depths [NEAR, FAR] instead of the image's range.",
          "mcdtool render.exr --dof-range 10 4 1.5 20 -o out.exr",
          [](const Call& c) {
              return mcdenoise::dof(c.dst, c.beauty, c.guide(Role::id), c.guide(Role::depth), c.integer(0),
                                    c.integer(1), c.number(2), c.number(3), {}, c.nthreads);
          } },
        { "cross-bilateral", "cross_bilateral", "cross_bilateral.h", { size_param }, {},
          format("Joint bilateral filter: spatial gaussian (sigma {}) times the feature weight of the "
                 "guides present (id: hard edge; normal, depth, albedo: gaussian falloff).",
                 mcdenoise::default_cross_bilateral_sigma_spatial),
          "mcdtool render.exr --cross-bilateral 7 -o clean.exr",
          [](const Call& c) {
              return mcdenoise::cross_bilateral(c.dst, c.beauty, feature_guides(c), c.integer(0),
                                                mcdenoise::default_cross_bilateral_sigma_spatial,
                                                mcdenoise::default_cross_bilateral_sigma_color, {}, {},
                                                c.nthreads);
          },
          roles_of(mcdenoise::cross_bilateral_guides) },
        { "atrous", "atrous", "atrous.h", { iterations_param }, {},
          "Edge-avoiding a-trous wavelet filter with SVGF's variance-guided luminance weight (variance "
          "estimated from the beauty when no variance guide is present) and the feature weight.",
          "mcdtool render.exr --demodulate --atrous 5 --remodulate -o clean.exr",
          [](const Call& c) {
              return mcdenoise::atrous(c.dst, c.beauty, feature_guides(c), c.integer(0),
                                       mcdenoise::default_atrous_sigma_luminance, {}, {}, c.nthreads);
          },
          roles_of(mcdenoise::atrous_guides) },
        { "nlmeans", "nlmeans", "nlmeans.h", { search_param }, {},
          format("Non-local means with variance-normalised {0}x{0} patch distances (strength {1}) and "
                 "the feature weight.",
                 2 * mcdenoise::default_nlmeans_patch_radius + 1, mcdenoise::default_nlmeans_strength),
          "mcdtool render.exr --nlmeans 7 -o clean.exr",
          [](const Call& c) {
              return mcdenoise::nlmeans(c.dst, c.beauty, feature_guides(c), c.integer(0),
                                        mcdenoise::default_nlmeans_patch_radius,
                                        mcdenoise::default_nlmeans_strength, {}, {}, c.nthreads);
          },
          roles_of(mcdenoise::nlmeans_guides) },
        { "denoise", "denoise_network", "denoise_network.h", {}, {},
          "The one-call denoiser. By default Open Image Denoise 2.x's trained networks (its "
          "published weights, run by mcdenoise's own engine) with OIDN's pipeline: autoexposure, "
          "the albedo and normal guides prefiltered, the beauty's network at high quality; with "
          "--temporal each frame's network result averaged across the frames that show the same "
          "thing. With :method=nlm (and, until the network has a light-pass mode, with --aovs) the "
          "NL-means operator: takes the firefly excess out, runs non-local means with the "
          "variance (from the variance guide, the halves, or estimated) and the feature weight of "
          "every guide present, and spreads the excess back over its neighbourhood, so the frame "
          "keeps its energy.",
          "mcdtool render.exr --denoise -o clean.exr",
          denoise_call, roles_of(mcdenoise::denoise_guides), true,
          { { "method", { "network", "nlm" },
              "network: Open Image Denoise 2.x's trained networks on the albedo and normal "
              "guides (docs/network.md); nlm: the NL-means operator below, network-free" },
            { "quality", { "high", "balanced", "fast" },
              "the network's size: high runs OIDN's large networks (its default), balanced the "
              "default ones, fast the small ones" },
            { "prefilter", { "1", "0" },
              "1: the albedo and normal guides are denoised by their own networks first "
              "(Blender's Accurate prefilter); 0: taken as they are" } } },
        { "clamp-fireflies", "clamp_fireflies", "fireflies.h", { factor_param }, {},
          format("Scale down pixels brighter than FACTOR times the 75th-percentile luminance of their "
                 "{0}x{0} neighbours (of the same object when an id guide is present).",
                 2 * mcdenoise::default_firefly_radius + 1),
          "mcdtool render.exr --clamp-fireflies 2 --object-median 7 -o clean.exr",
          [](const Call& c) {
              return mcdenoise::clamp_fireflies(c.dst, c.beauty, feature_guides(c), c.number(0),
                                                mcdenoise::default_firefly_radius, {}, c.nthreads);
          },
          roles_of(mcdenoise::clamp_fireflies_guides) },
        { "demodulate", "demodulate", "demodulate.h", {}, { Role::albedo },
          format("Divide the colour channels by albedo + {} so the next filters do not blur texture; "
                 "undo with --remodulate.",
                 mcdenoise::default_demodulate_epsilon),
          "mcdtool render.exr --demodulate --nlmeans 7 --remodulate -o clean.exr",
          [](const Call& c) {
              return mcdenoise::demodulate(c.dst, c.beauty, c.guide(Role::albedo),
                                           mcdenoise::default_demodulate_epsilon, {}, c.nthreads);
          } },
        { "remodulate", "remodulate", "demodulate.h", {}, { Role::albedo },
          format("Multiply the colour channels by albedo + {}: the inverse of --demodulate.",
                 mcdenoise::default_demodulate_epsilon),
          "mcdtool render.exr --demodulate --cross-bilateral 7 --remodulate -o clean.exr",
          [](const Call& c) {
              return mcdenoise::remodulate(c.dst, c.beauty, c.guide(Role::albedo),
                                           mcdenoise::default_demodulate_epsilon, {}, c.nthreads);
          } },
    };
    return table;
}

const Command* find_command(std::string_view name)
{
    for (const Command& command : command_table())
        if (name == command.name)
            return &command;
    return nullptr;
}

std::string command_usage(const Command& command)
{
    std::string usage = std::string("--") + command.name;
    for (const Param& param : command.params)
        usage += std::string(" ") + param.name;
    return usage;
}

}  // namespace mcdtool
