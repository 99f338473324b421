// denoise_network.cpp: the trained denoiser (mcdenoise/denoise_network.h):
// the guides checked, the pixels read as float RGB, the exposure measured,
// the guides prefiltered, the beauty's network run tile by tile, and only
// then `dst` written.
#include <mcdenoise/denoise_network.h>

#include "core/guides.h"
#include "core/operation.h"
#include "network/autoexposure.h"
#include "network/network_files.h"
#include "network/tiled_run.h"

#include <OpenImageIO/imagebufalgo.h>

#include <chrono>
#include <new>
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
    FloatRgb colour, albedo, normal;
    NetworkFiles files;
    std::string weights_dir;
    int tiles_done = 0, tiles_total = 0;

    /// Loads the weights file `name` into `net`.
    bool load(const std::string& name, UNet& net, std::string& error) const
    {
        const std::string path = weights_dir + "/" + name;
        const auto tensors     = shared_weights(path, error);
        return tensors && net.load(tensors, path, error);
    }

    /// The tile budget of `net`.
    long long tile_pixels(UNet& net, std::string& error) const
    {
        return options.memory_limit ? max_tile_pixels(net, options.memory_limit, error)
                                    : default_max_tile_pixels;
    }

    /// Runs `net` on `images` into `output`, reporting progress.
    bool run(UNet& net, const NetworkImages& images, const NetworkInput& input, const RgbOut& output,
             std::string& error)
    {
        const long long tile = tile_pixels(net, error);
        if (tile == 0)
            return false;
        const int before = tiles_done;
        auto progress    = [&](int done, int) {
            tiles_done = before + done;
            if (options.on_progress)
                options.on_progress(double(tiles_done) / double(std::max(tiles_total, tiles_done)));
        };
        return run_tiled(net, images, input, tile, output, nthreads, progress, error);
    }

    /// Denoises a guide by its prefilter network `name`, encoded as
    /// `encoding`, into `clean`.
    bool prefilter(const std::string& name, Encoding encoding, const RgbIn& guide, OwnedRgb& clean,
                   std::string& error)
    {
        UNet net;
        if (!load(name, net, error))
            return false;
        clean.values.resize(size_t(width) * height * 3);
        NetworkInput input;
        input.encoding = encoding;
        return run(net, { guide, {}, {} }, input, clean.out(width, height), error);
    }
};

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

/// The number of tiles `files` run over the image, for the progress.
int count_tiles(NetworkRun& run, std::string& error)
{
    int total = 0;
    for (const std::string* name : { &run.files.albedo_prefilter, &run.files.normal_prefilter,
                                     &run.files.beauty }) {
        if (name->empty())
            continue;
        UNet net;
        TilePlan plan;
        if (!run.load(*name, net, error))
            return -1;
        const long long tile = run.tile_pixels(net, error);
        if (tile == 0
            || !plan_tiles(run.width, run.height, net.layout().tile_overlap(), tile, plan, error))
            return -1;
        total += int(plan.tiles.size());
    }
    return total;
}

/// Runs the networks; `result` gets the denoised colour.
bool run_networks(NetworkRun& run, const Guides& guides, OwnedRgb& result, std::string& error)
{
    PhaseClock clock(run.options);
    const bool albedo = guides.albedo != nullptr, normal = guides.normal != nullptr && albedo;
    run.files = choose_network_files(run.options.quality, albedo, normal, run.options.prefilter_guides);
    if (!find_weights_dir(run.options.weights_dir, run.weights_dir, error))
        return false;
    run.tiles_total = count_tiles(run, error);
    if (run.tiles_total < 0)
        return false;
    clock.end("read weights");
    OwnedRgb clean_albedo, clean_normal;
    NetworkImages images { run.colour.pixels, albedo ? run.albedo.pixels : RgbIn {},
                           normal ? run.normal.pixels : RgbIn {} };
    if (!run.files.albedo_prefilter.empty()) {
        if (!run.prefilter(run.files.albedo_prefilter, Encoding::ldr, images.albedo, clean_albedo, error))
            return false;
        images.albedo = clean_albedo.in(run.width, run.height);
        clock.end("prefilter albedo");
    }
    if (!run.files.normal_prefilter.empty()) {
        if (!run.prefilter(run.files.normal_prefilter, Encoding::normal, images.normal, clean_normal,
                           error))
            return false;
        images.normal = clean_normal.in(run.width, run.height);
        clock.end("prefilter normal");
    }
    NetworkInput input;
    input.encoding = Encoding::hdr;
    input.albedo   = albedo;
    input.normal   = normal;
    autoexposure(images.main, input.input_scale);
    clock.end("autoexposure");
    UNet net;
    if (!run.load(run.files.beauty, net, error))
        return false;
    result.values.resize(size_t(run.width) * run.height * 3);
    if (!run.run(net, images, input, result.out(run.width, run.height), error))
        return false;
    clock.end("network");
    return true;
}

/// Writes the denoised colour and the beauty's other channels into `dst`.
bool write_result(ImageBuf& dst, const ImageBuf& beauty, const Guides& guides, const ROI& roi,
                  const OwnedRgb& colour)
{
    ResultPixels result;
    if (!begin_result(op_name, dst, beauty, { &beauty, guides.albedo, guides.normal }, roi, result))
        return false;
    const int extra = roi.chend - 3;
    std::vector<float> row(size_t(roi.width()) * size_t(std::max(extra, 0)));
    for (int y = roi.ybegin; y < roi.yend; ++y) {
        if (extra > 0) {
            const ROI line(roi.xbegin, roi.xend, y, y + 1, roi.zbegin, roi.zend, 3, roi.chend);
            beauty.get_pixels(line, OIIO::TypeFloat, row.data());
        }
        const float* rgb = colour.values.data() + size_t(y - roi.ybegin) * roi.width() * 3;
        for (int x = roi.xbegin; x < roi.xend; ++x) {
            float* out      = result.pixel(x, y);
            const size_t px = size_t(x - roi.xbegin);
            std::copy_n(rgb + 3 * px, 3, out);
            std::copy_n(row.data() + px * size_t(std::max(extra, 0)), std::max(extra, 0), out + 3);
        }
    }
    return finish_result(op_name, dst, result);
}

std::string guide_names(const Guides& guides)
{
    if (!guides.albedo)
        return "";
    return guides.normal ? "normal,albedo" : "albedo";
}

}  // namespace

const char* network_quality_name(NetworkQuality quality)
{
    switch (quality) {
    case NetworkQuality::fast: return "fast";
    case NetworkQuality::balanced: return "balanced";
    case NetworkQuality::high: return "high";
    }
    return "high";
}

bool parse_network_quality(const std::string& name, NetworkQuality& quality)
{
    for (NetworkQuality q : { NetworkQuality::fast, NetworkQuality::balanced, NetworkQuality::high })
        if (name == network_quality_name(q)) {
            quality = q;
            return true;
        }
    return false;
}

bool denoise_network(ImageBuf& dst, const ImageBuf& beauty, const Guides& guides,
                     const NetworkOptions& options, ROI roi, int nthreads)
{
    if (!resolve_roi(op_name, dst, beauty, roi) || !check_inputs(dst, beauty, guides, roi))
        return false;
    NetworkRun run(options, nthreads, roi.width(), roi.height());
    OwnedRgb colour;
    std::string error;
    try {
        if (!read_rgb(beauty, roi, run.colour) || (guides.albedo && !read_rgb(*guides.albedo, roi, run.albedo))
            || (guides.normal && !read_rgb(*guides.normal, roi, run.normal))) {
            dst.errorfmt("{}: cannot read the input pixels", op_name);
            return false;
        }
        if (!run_networks(run, guides, colour, error)) {
            dst.errorfmt("{}: {}", op_name, error);
            return false;
        }
    } catch (const std::bad_alloc&) {
        dst.errorfmt("{}: out of memory ({}x{} pixels); set a memory limit to tile the image", op_name,
                     run.width, run.height);
        return false;
    }
    if (!write_result(dst, beauty, guides, roi, colour))
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
