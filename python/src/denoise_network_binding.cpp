// denoise_network_binding.cpp: `mcdenoise.denoise_network`, the options of
// `NetworkOptions` as keyword arguments (the quality by name); with
// `neighbours`, a list of (offset, beauty, guides) or (offset,
// NetworkFrame) tuples, the cross-frame form; `prepare_network_frame`
// makes a NetworkFrame once for every call it is a neighbour in.
#include "denoise_network_binding.h"

#include "operation.h"

#include <mcdenoise/denoise_network.h>

#include <OpenImageIO/strutil.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace mcdpy {

namespace {

namespace mcd = mcdenoise;

/// The doc: denoise_network.h's, then the keyword arguments.
std::string network_doc()
{
    return std::string(library_doc("denoise_network"))
           + "\n\nKeyword arguments: `quality` (\"high\", \"balanced\" or \"fast\"),\n"
             "`prefilter_guides` (bool), `memory_limit` (bytes, 0 for OIDN's default\n"
             "tiles) and `weights_dir` (empty: $MCD_WEIGHTS_DIR, else the installed\n"
             "weights): the fields of NetworkOptions. With `neighbours`, a list of\n"
             "(offset, beauty, guides) tuples (offset: the neighbour's frame number\n"
             "minus this frame's; guides a dict, 'motion' among them if the shot has\n"
             "it) or (offset, NetworkFrame) from prepare_network_frame, the\n"
             "cross-frame form runs (each frame's network result accumulated across\n"
             "the frames that show the same thing).";
}

/// NetworkOptions from the keyword arguments; raises ValueError for an
/// unknown quality.
mcd::NetworkOptions network_options(const std::string& quality, bool prefilter_guides, uint64_t memory_limit,
                                    const std::string& weights_dir)
{
    mcd::NetworkOptions options;
    bool known = false;
    for (const mcd::NetworkQualityName& q : mcd::network_quality_names)
        if (quality == q.name) {
            options.quality = q.quality;
            known           = true;
        }
    if (!known)
        throw py::value_error("denoise_network: quality must be \"high\", \"balanced\" or \"fast\", not \""
                              + quality + "\"");
    options.prefilter_guides = prefilter_guides;
    options.memory_limit     = memory_limit;
    options.weights_dir      = weights_dir;
    return options;
}

/// A frame made from Python (`prepare_network_frame`), with the images it
/// refers to kept alive as long as it is.
struct NetworkFrameArg {
    py::object beauty_object, guides_object;  ///< the caller's objects (ImageBufs are borrowed)
    ImageArg beauty;
    std::unique_ptr<GuidesArg> guides;
    mcd::NetworkFrame frame;
};

/// `prepare_network_frame` of `beauty` and `guides` (a dict or None) with
/// `options`; raises mcdenoise.Error with the library's message.
std::shared_ptr<NetworkFrameArg> make_frame(const py::object& beauty, const py::object& guides,
                                            const mcd::NetworkOptions& options, int nthreads)
{
    auto f           = std::make_shared<NetworkFrameArg>();
    f->beauty_object = beauty;
    f->guides_object = guides;
    f->beauty        = beauty.cast<ImageArg>();
    f->guides        = std::make_unique<GuidesArg>(guides.cast<GuidesArg>());
    {
        py::gil_scoped_release release;
        f->frame = mcd::prepare_network_frame({ &f->beauty.image(), f->guides->guides() }, options, nthreads);
    }
    if (!f->frame.denoised)
        raise_library_error(f->frame.error);
    return f;
}

/// The neighbours, each a NetworkFrame (made here from (offset, beauty,
/// guides), or as given), and their offsets; raises TypeError naming an
/// item of another form.
void neighbour_frames(const py::object& object, const mcd::NetworkOptions& options, int nthreads,
                      std::vector<std::shared_ptr<NetworkFrameArg>>& frames, std::vector<int>& offsets)
{
    if (!py::isinstance<py::sequence>(object))
        throw py::type_error("neighbours: expected a list of (offset, beauty, guides) tuples");
    const py::sequence items = object.cast<py::sequence>();
    for (size_t i = 0; i < items.size(); ++i) {
        const py::object item = items[i];
        const bool tuple      = py::isinstance<py::tuple>(item);
        const bool made = tuple && py::len(item) == 2 && py::isinstance<NetworkFrameArg>(item.cast<py::tuple>()[1]);
        if (!tuple || (py::len(item) != 3 && !made))
            throw py::type_error(OIIO::Strutil::fmt::format(
                "neighbours[{}]: expected a tuple (offset, beauty, guides) or (offset, NetworkFrame)", i));
        const py::tuple t = item.cast<py::tuple>();
        offsets.push_back(t[0].cast<int>());
        frames.push_back(made ? t[1].cast<std::shared_ptr<NetworkFrameArg>>()
                              : make_frame(t[1], t[2], options, nthreads));
    }
}

}  // namespace

void bind_denoise_network(py::module_& m)
{
    static const std::string doc = network_doc();
    m.def(
        "denoise_network",
        [](const py::object& beauty_object, const py::object& guides_object, const py::object& neighbours,
           const std::string& quality, bool prefilter_guides, uint64_t memory_limit, const std::string& weights_dir,
           ROI roi, int nthreads) -> py::object {
            const mcd::NetworkOptions options = network_options(quality, prefilter_guides, memory_limit, weights_dir);
            const ImageArg beauty = beauty_object.cast<ImageArg>();
            if (neighbours.is_none()) {
                const GuidesArg guides = guides_object.cast<GuidesArg>();
                ImageBuf result        = [&] {
                    py::gil_scoped_release release;
                    return mcd::denoise_network(beauty.image(), guides.guides(), options, roi, nthreads);
                }();
                return to_python(std::move(result), beauty);
            }
            std::vector<std::shared_ptr<NetworkFrameArg>> frames;
            std::vector<int> offsets;
            neighbour_frames(neighbours, options, nthreads, frames, offsets);
            const auto centre = make_frame(beauty_object, guides_object, options, nthreads);
            std::vector<mcd::NetworkFrame> made;
            for (const auto& f : frames)
                made.push_back(f->frame);
            ImageBuf result = [&] {
                py::gil_scoped_release release;
                return mcd::denoise_network(centre->frame, made, offsets, roi, nthreads);
            }();
            return to_python(std::move(result), beauty);
        },
        doc.c_str(), py::arg("beauty"), py::arg("guides") = py::none(), py::kw_only(),
        py::arg("neighbours") = py::none(), py::arg("quality") = "high", py::arg("prefilter_guides") = true,
        py::arg("memory_limit") = 0, py::arg("weights_dir") = "", py::arg_v("roi", ROI(), "ROI.All"),
        py::arg("nthreads") = 0);
    py::class_<NetworkFrameArg, std::shared_ptr<NetworkFrameArg>>(
        m, "NetworkFrame",
        "A frame made once with prepare_network_frame (prepared, and denoised by\n"
        "the network alone), for every denoise_network call it is a neighbour in:\n"
        "pass it as (offset, frame) in `neighbours`, with the same options. It\n"
        "keeps its beauty and guides alive.");
    m.def(
        "prepare_network_frame",
        [](const py::object& beauty, const py::object& guides, const std::string& quality, bool prefilter_guides,
           uint64_t memory_limit, const std::string& weights_dir, int nthreads) {
            return make_frame(beauty, guides, network_options(quality, prefilter_guides, memory_limit, weights_dir),
                              nthreads);
        },
        library_doc("prepare_network_frame"), py::arg("beauty"), py::arg("guides") = py::none(), py::kw_only(),
        py::arg("quality") = "high", py::arg("prefilter_guides") = true, py::arg("memory_limit") = 0,
        py::arg("weights_dir") = "", py::arg("nthreads") = 0);
}

}  // namespace mcdpy
