// sequence_metrics.h: binds the sequence metrics (sequence_metrics.h of the
// library): all at once over lists of frames, or frame by frame.
#pragma once

#include <pybind11/pybind11.h>

namespace mcdpy {

namespace py = pybind11;

/// Adds SequenceComparison, SequenceSums and the sequence metric functions
/// to `module`, with the library's names and doc comments.
void bind_sequence_metrics(py::module_& module);

}  // namespace mcdpy
