// denoise_binding.cpp: the `denoise` binding. Neighbouring frames come as a
// list of (offset, beauty, guides) tuples, offset the frame number minus the
// centre's; without them the single-frame form runs.
#include "denoise_binding.h"

#include "operation.h"

#include <mcdenoise/temporal.h>

#include <OpenImageIO/strutil.h>

#include <memory>
#include <vector>

namespace mcdpy {

namespace {

namespace mcd = mcdenoise;

/// The neighbouring frames passed from Python, kept alive for the call.
struct NeighboursArg {
    std::vector<ImageArg> beauties;
    std::vector<std::unique_ptr<GuidesArg>> guides;
    std::vector<mcd::FrameInput> frames;
    std::vector<int> offsets;
};

/// Reads [(offset, beauty, guides), ...]; raises TypeError naming the item.
NeighboursArg neighbours_arg(const py::object& object)
{
    if (!py::isinstance<py::sequence>(object))
        throw py::type_error("neighbours: expected a list of (offset, beauty, guides) tuples");
    const py::sequence items = object.cast<py::sequence>();
    NeighboursArg arg;
    arg.beauties.reserve(items.size());
    for (size_t i = 0; i < items.size(); ++i) {
        const py::object item = items[i];
        if (!py::isinstance<py::tuple>(item) || py::len(item) != 3)
            throw py::type_error(OIIO::Strutil::fmt::format(
                "neighbours[{}]: expected a tuple (offset, beauty, guides)", i));
        const py::tuple tuple = item.cast<py::tuple>();
        arg.offsets.push_back(tuple[0].cast<int>());
        arg.beauties.push_back(tuple[1].cast<ImageArg>());
        arg.guides.push_back(std::make_unique<GuidesArg>(tuple[2].cast<GuidesArg>()));
    }
    for (size_t i = 0; i < arg.beauties.size(); ++i)
        arg.frames.push_back(mcd::FrameInput{ &arg.beauties[i].image(), arg.guides[i]->guides() });
    return arg;
}

/// The doc: denoise.h's, then temporal.h's for the neighbours.
std::string denoise_doc()
{
    return std::string(library_doc("denoise"))
           + "\n\nWith `neighbours`, a list of (offset, beauty, guides) tuples (offset: the\n"
             "neighbour's frame number minus this frame's; guides: a dict like `guides`,\n"
             "with 'motion' among them if the shot has it), the cross-frame form of\n"
             "temporal.h runs; an empty list gives the single-frame result.";
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
                return mcd::denoise(mcd::FrameInput{ &beauty.image(), guides.guides() }, frames.frames,
                                    frames.offsets, roi, nthreads);
            }();
            return to_python(std::move(result), beauty);
        },
        doc.c_str(), py::arg("beauty"), py::arg("guides") = py::none(),
        py::arg("neighbours") = py::none(), py::arg_v("roi", ROI(), "ROI.All"), py::arg("nthreads") = 0);
}

}  // namespace mcdpy
