// denoise_binding.cpp: the `denoise` binding. Neighbouring frames come as a
// list of (offset, beauty, guides) tuples, offset the frame number minus the
// centre's, or (offset, PreparedFrame) for frames prepared once
// (`prepare_frame`); without them the single-frame form runs.
#include "denoise_binding.h"

#include "operation.h"

#include <mcdenoise/temporal.h>

#include <OpenImageIO/strutil.h>

#include <algorithm>
#include <memory>
#include <vector>

namespace mcdpy {

namespace {

namespace mcd = mcdenoise;

/// A frame prepared from Python (`prepare_frame`), with the images it
/// refers to kept alive as long as it is.
struct PreparedArg {
    py::object beauty_object, guides_object;  ///< the caller's objects (ImageBufs are borrowed)
    ImageArg beauty;
    std::unique_ptr<GuidesArg> guides;
    mcd::PreparedFrame frame;
};

/// `prepare_frame` of `beauty` and `guides` (a dict or None); raises
/// mcdenoise.Error with the library's message.
std::shared_ptr<PreparedArg> prepare(const py::object& beauty, const py::object& guides, int nthreads)
{
    auto p = std::make_shared<PreparedArg>();
    p->beauty_object = beauty;
    p->guides_object = guides;
    p->beauty = beauty.cast<ImageArg>();
    p->guides = std::make_unique<GuidesArg>(guides.cast<GuidesArg>());
    {
        py::gil_scoped_release release;
        p->frame = mcd::prepare_frame(mcd::FrameInput{ &p->beauty.image(), p->guides->guides() }, nthreads);
    }
    if (!p->frame.data)
        raise_library_error(p->frame.error);
    return p;
}

/// The neighbouring frames passed from Python, kept alive for the call:
/// each as given, or prepared (`prepared[i]` set) when given prepared.
struct NeighboursArg {
    std::vector<ImageArg> beauties;
    std::vector<std::unique_ptr<GuidesArg>> guides;
    std::vector<mcd::FrameInput> frames;
    std::vector<std::shared_ptr<PreparedArg>> prepared;
    std::vector<int> offsets;

    bool any_prepared() const
    {
        return std::any_of(prepared.begin(), prepared.end(), [](const auto& p) { return p != nullptr; });
    }
};

/// Reads [(offset, beauty, guides) or (offset, PreparedFrame), ...]; raises
/// TypeError naming the item.
NeighboursArg neighbours_arg(const py::object& object)
{
    if (!py::isinstance<py::sequence>(object))
        throw py::type_error("neighbours: expected a list of (offset, beauty, guides) tuples");
    const py::sequence items = object.cast<py::sequence>();
    NeighboursArg arg;
    arg.beauties.reserve(items.size());
    for (size_t i = 0; i < items.size(); ++i) {
        const py::object item = items[i];
        const bool tuple = py::isinstance<py::tuple>(item);
        const bool prepared = tuple && py::len(item) == 2
                              && py::isinstance<PreparedArg>(item.cast<py::tuple>()[1]);
        if (!tuple || (py::len(item) != 3 && !prepared))
            throw py::type_error(OIIO::Strutil::fmt::format(
                "neighbours[{}]: expected a tuple (offset, beauty, guides) or (offset, PreparedFrame)", i));
        const py::tuple t = item.cast<py::tuple>();
        arg.offsets.push_back(t[0].cast<int>());
        arg.prepared.push_back(prepared ? t[1].cast<std::shared_ptr<PreparedArg>>() : nullptr);
        arg.beauties.push_back(prepared ? ImageArg() : t[1].cast<ImageArg>());
        arg.guides.push_back(std::make_unique<GuidesArg>(prepared ? GuidesArg() : t[2].cast<GuidesArg>()));
    }
    for (size_t i = 0; i < arg.beauties.size(); ++i)
        arg.frames.push_back(arg.prepared[i]
                                 ? mcd::FrameInput{ &arg.prepared[i]->beauty.image(), arg.prepared[i]->guides->guides() }
                                 : mcd::FrameInput{ &arg.beauties[i].image(), arg.guides[i]->guides() });
    return arg;
}

/// The cross-frame denoise with some neighbours prepared: the centre and
/// the others prepared here, then the form of prepared frames.
ImageBuf denoise_prepared(const ImageArg& beauty, const GuidesArg& guides, const NeighboursArg& n, ROI roi,
                          int nthreads)
{
    std::vector<mcd::PreparedFrame> frames;
    for (size_t i = 0; i < n.frames.size(); ++i)
        frames.push_back(n.prepared[i] ? n.prepared[i]->frame : mcd::prepare_frame(n.frames[i], nthreads));
    return mcd::denoise(mcd::prepare_frame(mcd::FrameInput{ &beauty.image(), guides.guides() }, nthreads), frames,
                        n.offsets, roi, nthreads);
}

/// The doc: denoise.h's, then temporal.h's for the neighbours.
std::string denoise_doc()
{
    return std::string(library_doc("denoise"))
           + "\n\nWith `neighbours`, a list of (offset, beauty, guides) tuples (offset: the\n"
             "neighbour's frame number minus this frame's; guides: a dict like `guides`,\n"
             "with 'motion' among them if the shot has it), the cross-frame form of\n"
             "temporal.h runs; an empty list gives the single-frame result. A\n"
             "neighbour may be given as (offset, PreparedFrame) instead (prepare_frame:\n"
             "prepared once for every call it is in); the result is the same.";
}

}  // namespace

void bind_denoise(py::module_& m)
{
    static const std::string doc = denoise_doc();
    m.def(
        "denoise",
        [](const ImageArg& beauty, const GuidesArg& guides, const py::object& neighbours, ROI roi,
           int nthreads) -> py::object {
            const bool across_frames = !neighbours.is_none();
            const NeighboursArg frames = across_frames ? neighbours_arg(neighbours) : NeighboursArg{};
            ImageBuf result = [&] {
                py::gil_scoped_release release;
                if (!across_frames)
                    return mcd::denoise(beauty.image(), guides.guides(), roi, nthreads);
                if (frames.any_prepared())
                    return denoise_prepared(beauty, guides, frames, roi, nthreads);
                return mcd::denoise(mcd::FrameInput{ &beauty.image(), guides.guides() }, frames.frames,
                                    frames.offsets, roi, nthreads);
            }();
            return to_python(std::move(result), beauty);
        },
        doc.c_str(), py::arg("beauty"), py::arg("guides") = py::none(),
        py::arg("neighbours") = py::none(), py::arg_v("roi", ROI(), "ROI.All"), py::arg("nthreads") = 0);
    py::class_<PreparedArg, std::shared_ptr<PreparedArg>>(
        m, "PreparedFrame",
        "A frame prepared once with prepare_frame, for every denoise call it is a\n"
        "neighbour in: pass it as (offset, prepared) in `neighbours`. It keeps its\n"
        "beauty and guides alive.");
    m.def(
        "prepare_frame",
        [](const py::object& beauty, const py::object& guides, int nthreads) { return prepare(beauty, guides, nthreads); },
        library_doc("prepare_frame"), py::arg("beauty"), py::arg("guides") = py::none(), py::arg("nthreads") = 0);
}

}  // namespace mcdpy
