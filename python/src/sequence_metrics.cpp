// sequence_metrics.cpp: the sequence metrics' bindings. Frames are lists of
// ImageBufs or numpy arrays; a failed comparison raises mcdenoise.Error.
#include "sequence_metrics.h"

#include "operation.h"

#include <mcdenoise/sequence_metrics.h>

#include <pybind11/stl.h>

#include <vector>

namespace mcdpy {

namespace {

namespace mcd = mcdenoise;
using py::arg;

/// The library's view of a list of frames.
std::vector<const ImageBuf*> frame_pointers(const std::vector<ImageArg>& frames)
{
    std::vector<const ImageBuf*> pointers;
    for (const ImageArg& frame : frames)
        pointers.push_back(&frame.image());
    return pointers;
}

/// The figures, after raising the library's error if there is one.
mcd::SequenceComparison checked(mcd::SequenceComparison&& figures)
{
    if (!figures.ok)
        raise_library_error(figures.error);
    return std::move(figures);
}

void bind_records(py::module_& m)
{
    using mcd::SequenceComparison;
    py::class_<SequenceComparison>(m, "SequenceComparison",
                                   "The figures of a sequence against its references (see compare_sequence).")
        .def_readonly("frame_rel_mse", &SequenceComparison::frame_rel_mse)
        .def_readonly("mean_rel_mse", &SequenceComparison::mean_rel_mse)
        .def_readonly("temporal_error", &SequenceComparison::temporal_error)
        .def_readonly("flicker", &SequenceComparison::flicker)
        .def_readonly("frames", &SequenceComparison::frames)
        .def_readonly("pixels", &SequenceComparison::pixels)
        .def("__repr__", [](const SequenceComparison& s) {
            return py::str("SequenceComparison(frames={}, mean_rel_mse={}, temporal_error={}, flicker={})")
                .format(s.frames, s.mean_rel_mse, s.temporal_error, s.flicker);
        });
    py::class_<mcd::SequenceSums>(m, "SequenceSums",
                                  "The running sums of a frame-by-frame sequence comparison (see "
                                  "start_sequence).");
}

}  // namespace

void bind_sequence_metrics(py::module_& m)
{
    bind_records(m);
    using Frames = const std::vector<ImageArg>&;
    m.def(
        "compare_sequence",
        [](Frames results, Frames references, ROI roi, int nthreads) {
            py::gil_scoped_release release;
            return checked(mcd::compare_sequence(frame_pointers(results), frame_pointers(references), roi, nthreads));
        },
        library_doc("compare_sequence"), arg("results"), arg("references"), py::arg_v("roi", ROI(), "ROI.All"),
        arg("nthreads") = 0);
    m.def(
        "temporal_error",
        [](Frames results, Frames references, ROI roi, int nthreads) {
            py::gil_scoped_release release;
            return mcd::temporal_error(frame_pointers(results), frame_pointers(references), roi, nthreads);
        },
        library_doc("temporal_error"), arg("results"), arg("references"), py::arg_v("roi", ROI(), "ROI.All"),
        arg("nthreads") = 0);
    m.def(
        "flicker",
        [](Frames results, Frames references, ROI roi, int nthreads) {
            py::gil_scoped_release release;
            return mcd::flicker(frame_pointers(results), frame_pointers(references), roi, nthreads);
        },
        library_doc("flicker"), arg("results"), arg("references"), py::arg_v("roi", ROI(), "ROI.All"),
        arg("nthreads") = 0);
    m.def("start_sequence", &mcd::start_sequence, library_doc("start_sequence"), py::arg_v("roi", ROI(), "ROI.All"),
          py::arg("nthreads") = 0);
    m.def(
        "add_sequence_frame",
        [](mcd::SequenceSums& sums, const ImageArg& result, const ImageArg& reference) {
            py::gil_scoped_release release;
            return mcd::add_sequence_frame(sums, result.image(), reference.image());
        },
        library_doc("add_sequence_frame"), arg("sums"), arg("result"), arg("reference"));
    m.def(
        "sequence_comparison", [](const mcd::SequenceSums& sums) { return checked(mcd::sequence_comparison(sums)); },
        library_doc("sequence_comparison"), arg("sums"));
}

}  // namespace mcdpy
