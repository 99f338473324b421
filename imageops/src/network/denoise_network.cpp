// denoise_network.cpp: the trained denoiser (mcdenoise/denoise_network.h):
// the guides checked, the pixels read as float RGB and every weight file
// loaded before `dst` is touched; then the guides prefiltered, the exposure
// measured and the beauty's network run tile by tile straight into `dst`.
#include <mcdenoise/denoise_network.h>

#include "core/guides.h"
#include "core/operation.h"
#include "network/autoexposure.h"
#include "network/network_files.h"
#include "network/tiled_run.h"
#include "network/tiling.h"

#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <chrono>
#include <new>
#include <utility>
#include <vector>

namespace mcdenoise {

namespace {

const char* const op_name = "denoise_network";

/// RGB pixels of an image over a region: `storage` when the image's own
/// pixels cannot be pointed at.
struct FloatRgb {
    RgbIn pixels;
    std::vector<float> storage;
};

/// Channels 0-2 of `image` over `roi` (x, y only); a 1-channel image is
/// taken as grey. Points into `image` when it holds local float pixels.
bool read_rgb(const ImageBuf& image, const ROI& roi, FloatRgb& rgb)
{
    const OIIO::ImageSpec& spec = image.spec();
    if (image.localpixels() && spec.format == OIIO::TypeFloat && spec.nchannels >= 3) {
        rgb.pixels = { static_cast<const float*>(image.pixeladdr(roi.xbegin, roi.ybegin)), roi.width(),
                       roi.height(), spec.nchannels, std::ptrdiff_t(spec.width) * spec.nchannels };
        return true;
    }
    const int channels = spec.nchannels >= 3 ? 3 : 1;
    ROI read           = roi;
    read.chbegin       = 0;
    read.chend         = channels;
    std::vector<float> values(size_t(roi.width()) * roi.height() * channels);
    if (!image.get_pixels(read, OIIO::TypeFloat, values.data()))
        return false;
    if (channels == 1) {
        rgb.storage.resize(values.size() * 3);
        for (size_t i = 0; i < values.size(); ++i)
            rgb.storage[3 * i] = rgb.storage[3 * i + 1] = rgb.storage[3 * i + 2] = values[i];
    } else {
        rgb.storage = std::move(values);
    }
    rgb.pixels = { rgb.storage.data(), roi.width(), roi.height(), 3, std::ptrdiff_t(roi.width()) * 3 };
    return true;
}

/// An RGB image of its own, written by a network.
struct OwnedRgb {
    std::vector<float> values;
    RgbOut out(int width, int height) { return { values.data(), width, height, 3, std::ptrdiff_t(width) * 3 }; }
    RgbIn in(int width, int height) const
    {
        return { values.data(), width, height, 3, std::ptrdiff_t(width) * 3 };
    }
};

/// Times each phase and reports it to the caller's callback.
class PhaseClock {
public:
    explicit PhaseClock(const NetworkOptions& options)
        : options_(options), start_(std::chrono::steady_clock::now())
    {
    }
    void end(const std::string& phase)
    {
        const auto now = std::chrono::steady_clock::now();
        if (options_.on_phase)
            options_.on_phase(phase, std::chrono::duration<double>(now - start_).count());
        start_ = now;
    }

private:
    const NetworkOptions& options_;
    std::chrono::steady_clock::time_point start_;
};

/// Everything a denoise runs: the images, the networks and their tiles.
struct NetworkRun {
    NetworkRun(const NetworkOptions& options_, int nthreads_, int width_, int height_)
        : options(options_), nthreads(nthreads_), width(width_), height(height_)
    {
    }

    const NetworkOptions& options;
    int nthreads;
    int width, height;
    int result_channels = 3;
    FloatRgb colour, albedo, normal;
    NetworkFiles files;
    UNet beauty_net, albedo_net, normal_net;
    int tiles_done = 0, tiles_total = 0;

    /// The bytes held for the whole run besides the networks' tiles: the
    /// pixels copied in, the prefiltered guides and the result's
    /// `result_channels` channels.
    uint64_t held_bytes() const
    {
        const uint64_t image = uint64_t(width) * uint64_t(height) * 3 * sizeof(float);
        uint64_t held        = (colour.storage.size() + albedo.storage.size() + normal.storage.size())
                        * sizeof(float)
                    + image / 3 * uint64_t(result_channels);
        for (const std::string* name : { &files.albedo_prefilter, &files.normal_prefilter })
            held += name->empty() ? 0 : image;
        return held;
    }

    /// The most pixels a tile of `net` may have, and its smallest side.
    bool tile_limits(UNet& net, long long& pixels, int& min_side, std::string& error) const
    {
        if (!options.memory_limit) {
            pixels   = default_max_tile_pixels;
            min_side = 0;
            return true;
        }
        const uint64_t held = held_bytes();
        pixels   = max_tile_pixels(net, options.memory_limit > held ? options.memory_limit - held : 1, error);
        min_side = memory_limited_min_side(net);
        return pixels > 0;
    }

    /// Runs `net` on `images` into `output`, reporting progress.
    bool run(UNet& net, const NetworkImages& images, const NetworkInput& input, const RgbOut& output,
             std::string& error)
    {
        long long pixels = 0;
        int min_side     = 0;
        if (!tile_limits(net, pixels, min_side, error))
            return false;
        const int before = tiles_done;
        auto progress    = [&](int done, int) {
            tiles_done = before + done;
            if (options.on_progress)
                options.on_progress(double(tiles_done) / double(std::max(tiles_total, tiles_done)));
        };
        const bool ok = run_tiled(net, images, input, pixels, min_side, output, nthreads, progress, error);
        net.release_plan();  // the next network's tiles get the memory
        return ok;
    }
};

/// Loads the weights file `name` of `dir` into `net`.
bool load_network(const std::string& dir, const std::string& name, UNet& net, std::string& error)
{
    const std::string path = dir + "/" + name;
    const auto tensors     = shared_weights(path, error);
    return tensors && net.load(tensors, path, error);
}

bool check_inputs(ImageBuf& dst, const ImageBuf& beauty, const Guides& guides, const ROI& roi)
{
    if (beauty.nchannels() < 3 || roi.chbegin != 0 || roi.chend < 3) {
        dst.errorfmt("{}: the network denoises colour: the beauty needs 3 channels and the ROI "
                     "channels 0-2 (it has {} channels, ROI channels {}-{})",
                     op_name, beauty.nchannels(), roi.chbegin, roi.chend - 1);
        return false;
    }
    if (guides.albedo
        && !check_guide(op_name, "albedo", dst, *guides.albedo,
                        guides.albedo->nchannels() == 1 ? 1 : 3, roi))
        return false;
    return !guides.normal || check_guide(op_name, "normal", dst, *guides.normal, 3, roi);
}

/// Chooses and loads the networks and counts their tiles: everything that
/// can fail on bad input (a missing or corrupt weight file) before `dst`
/// is touched.
bool load_networks(NetworkRun& run, const Guides& guides, std::string& error)
{
    const bool albedo = guides.albedo != nullptr, normal = guides.normal != nullptr && albedo;
    run.files = choose_network_files(run.options.quality, albedo, normal, run.options.prefilter_guides);
    std::string dir;
    if (!find_weights_dir(run.options.weights_dir, dir, error))
        return false;
    const std::pair<const std::string*, UNet*> nets[] = { { &run.files.albedo_prefilter, &run.albedo_net },
                                                          { &run.files.normal_prefilter, &run.normal_net },
                                                          { &run.files.beauty, &run.beauty_net } };
    run.tiles_total = 0;
    for (const auto& [name, net] : nets) {
        if (name->empty())
            continue;
        long long pixels = 0;
        int min_side     = 0;
        TilePlan plan;
        if (!load_network(dir, *name, *net, error) || !run.tile_limits(*net, pixels, min_side, error)
            || !plan_tiles(run.width, run.height, net->layout().tile_overlap(), pixels, plan, error,
                           min_side))
            return false;
        run.tiles_total += int(plan.tiles.size());
    }
    return true;
}

/// Runs the networks: the guides' prefilters, the exposure, the beauty's
/// network into `output`.
bool run_networks(NetworkRun& run, const Guides& guides, const RgbOut& output, PhaseClock& clock,
                  std::string& error)
{
    const bool albedo = guides.albedo != nullptr, normal = guides.normal != nullptr && albedo;
    OwnedRgb clean_albedo, clean_normal;
    NetworkImages images { run.colour.pixels, albedo ? run.albedo.pixels : RgbIn {},
                           normal ? run.normal.pixels : RgbIn {} };
    const struct {
        const std::string& file;
        UNet& net;
        Encoding encoding;
        RgbIn& guide;
        OwnedRgb& clean;
        const char* phase;
    } prefilters[] = { { run.files.albedo_prefilter, run.albedo_net, Encoding::ldr, images.albedo,
                         clean_albedo, "prefilter albedo" },
                       { run.files.normal_prefilter, run.normal_net, Encoding::normal, images.normal,
                         clean_normal, "prefilter normal" } };
    for (const auto& p : prefilters) {
        if (p.file.empty())
            continue;
        p.clean.values.resize(size_t(run.width) * run.height * 3);
        NetworkInput input;
        input.encoding = p.encoding;
        if (!run.run(p.net, { p.guide, {}, {} }, input, p.clean.out(run.width, run.height), error))
            return false;
        p.guide = p.clean.in(run.width, run.height);
        clock.end(p.phase);
    }
    NetworkInput input;
    input.encoding = Encoding::hdr;
    input.albedo   = albedo;
    input.normal   = normal;
    autoexposure(images.main, input.input_scale);
    clock.end("autoexposure");
    if (!run.run(run.beauty_net, images, input, output, error))
        return false;
    clock.end("network");
    return true;
}

/// The RGB part of `result`, where the beauty's network writes.
RgbOut result_rgb(const ResultPixels& result, const ROI& roi)
{
    float* first            = result.pixel(roi.xbegin, roi.ybegin);
    const std::ptrdiff_t row = roi.height() > 1 ? result.pixel(roi.xbegin, roi.ybegin + 1) - first
                                                : result.pixel_stride() * roi.width();
    return { first, roi.width(), roi.height(), result.pixel_stride(), row };
}

/// Copies the beauty's channels past the colour (alpha) into `result`.
void copy_further_channels(const ImageBuf& beauty, const ROI& roi, ResultPixels& result)
{
    const int extra = roi.chend - 3;
    if (extra <= 0)
        return;
    std::vector<float> row(size_t(roi.width()) * size_t(extra));
    for (int y = roi.ybegin; y < roi.yend; ++y) {
        const ROI line(roi.xbegin, roi.xend, y, y + 1, roi.zbegin, roi.zend, 3, roi.chend);
        beauty.get_pixels(line, OIIO::TypeFloat, row.data());
        for (int x = roi.xbegin; x < roi.xend; ++x)
            std::copy_n(row.data() + size_t(x - roi.xbegin) * size_t(extra), extra, result.pixel(x, y) + 3);
    }
}

std::string guide_names(const Guides& guides)
{
    if (!guides.albedo)
        return "";
    return guides.normal ? "normal,albedo" : "albedo";
}

}  // namespace

bool denoise_network(ImageBuf& dst, const ImageBuf& beauty, const Guides& guides,
                     const NetworkOptions& options, ROI roi, int nthreads)
{
    if (!resolve_roi(op_name, dst, beauty, roi) || !check_inputs(dst, beauty, guides, roi))
        return false;
    NetworkRun run(options, nthreads, roi.width(), roi.height());
    run.result_channels = roi.chend - roi.chbegin;
    PhaseClock clock(options);
    std::string error;
    ResultPixels result;
    try {
        if (!read_rgb(beauty, roi, run.colour) || (guides.albedo && !read_rgb(*guides.albedo, roi, run.albedo))
            || (guides.normal && !read_rgb(*guides.normal, roi, run.normal))) {
            dst.errorfmt("{}: cannot read the input pixels", op_name);
            return false;
        }
        if (!load_networks(run, guides, error)) {
            dst.errorfmt("{}: {}", op_name, error);
            return false;
        }
        clock.end("read weights");
        if (!begin_result(op_name, dst, beauty, { &beauty, guides.albedo, guides.normal }, roi, result))
            return false;
        if (!run_networks(run, guides, result_rgb(result, roi), clock, error)) {
            dst.errorfmt("{}: {}", op_name, error);
            return false;
        }
    } catch (const std::bad_alloc&) {
        dst.errorfmt("{}: out of memory ({}x{} pixels); a memory limit tiles the image", op_name,
                     run.width, run.height);
        return false;
    }
    copy_further_channels(beauty, roi, result);
    if (!finish_result(op_name, dst, result))
        return false;
    dst.specmod().attribute("mcdenoise:denoise_guides", guide_names(guides));
    std::string networks = run.files.beauty;
    for (const std::string* name : { &run.files.albedo_prefilter, &run.files.normal_prefilter })
        if (!name->empty())
            networks += "," + *name;
    dst.specmod().attribute("mcdenoise:network", networks);
    return true;
}

ImageBuf denoise_network(const ImageBuf& beauty, const Guides& guides, const NetworkOptions& options,
                         ROI roi, int nthreads)
{
    return value_form(
        [&](ImageBuf& dst) { return denoise_network(dst, beauty, guides, options, roi, nthreads); });
}

}  // namespace mcdenoise
