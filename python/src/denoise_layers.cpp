// denoise_layers.cpp: `mcdenoise.denoise(beauty, guides, layers=[...])`,
// the overload of `denoise` that also denoises light passes with the
// beauty's weights (`denoise_layers`), returning (beauty, [layers]).
#include "denoise_layers.h"

#include "operation.h"

#include <mcdenoise/denoise_layers.h>

#include <pybind11/stl.h>

#include <vector>

namespace mcdpy {

namespace {

/// `denoise_layers` as Python sees it: (denoised beauty, [denoised layers]),
/// each in the kind it came in.
py::object denoise_with_layers(const ImageArg& beauty, const std::vector<ImageArg>& layers,
                               const GuidesArg& guides, ROI roi, int nthreads)
{
    std::vector<const ImageBuf*> inputs;
    for (const ImageArg& layer : layers)
        inputs.push_back(&layer.image());
    std::vector<ImageBuf> results = [&] {
        py::gil_scoped_release release;
        return mcdenoise::denoise_layers(beauty.image(), inputs, guides.guides(), roi, nthreads);
    }();
    py::object denoised = to_python(std::move(results[0]), beauty);
    py::list out_layers;
    for (size_t i = 1; i < results.size(); ++i)
        out_layers.append(layers[i - 1].to_python(std::move(results[i])));
    return py::make_tuple(denoised, out_layers);
}

}  // namespace

void bind_denoise_layers(py::module_& m)
{
    const std::string doc = std::string("With `layers`: returns (denoised beauty, [denoised layers]).\n\n")
                            + library_doc("denoise_layers");
    m.def("denoise", &denoise_with_layers, doc.c_str(), py::arg("beauty"), py::kw_only(), py::arg("layers"),
          py::arg("guides") = py::none(), py::arg_v("roi", ROI(), "ROI.All"), py::arg("nthreads") = 0);
    m.def("denoise_layers", &denoise_with_layers, library_doc("denoise_layers"), py::arg("beauty"),
          py::arg("layers"), py::arg("guides") = py::none(), py::arg_v("roi", ROI(), "ROI.All"),
          py::arg("nthreads") = 0);
}

}  // namespace mcdpy
