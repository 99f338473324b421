// denoise_layers.cpp: `mcdenoise.denoise(beauty, guides, layers=[...])`,
// the overload of `denoise` that also denoises light passes with the
// beauty's weights (`denoise_layers`), returning (beauty, [layers]);
// `sums` and `colours` say how the layers rebuild the beauty.
#include "denoise_layers.h"

#include "operation.h"

#include <mcdenoise/denoise_layers.h>

#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <vector>

namespace mcdpy {

namespace {

using Sums    = std::optional<std::vector<int>>;
using Colours = std::optional<std::vector<std::optional<ImageArg>>>;

/// The layer terms of `sums` and `colours` (each None, or one per layer;
/// a colour may be None).
std::vector<mcdenoise::LayerTerm> layer_terms(size_t nlayers, const Sums& given_sums,
                                              const Colours& given_colours)
{
    static const Sums::value_type no_sums;
    static const Colours::value_type no_colours;
    const auto& sums    = given_sums ? *given_sums : no_sums;
    const auto& colours = given_colours ? *given_colours : no_colours;
    if ((!sums.empty() && sums.size() != nlayers) || (!colours.empty() && colours.size() != nlayers))
        throw py::value_error("denoise_layers: sums and colours need one entry per layer");
    std::vector<mcdenoise::LayerTerm> terms;
    if (sums.empty() && colours.empty())
        return terms;
    terms.resize(nlayers);
    for (size_t i = 0; i < nlayers; ++i) {
        if (!sums.empty())
            terms[i].sum = sums[i];
        if (!colours.empty() && colours[i])
            terms[i].colour = &colours[i]->image();
    }
    return terms;
}

/// `denoise_layers` as Python sees it: (denoised beauty, [denoised layers]),
/// each in the kind it came in.
py::object denoise_with_layers(const ImageArg& beauty, const std::vector<ImageArg>& layers,
                               const GuidesArg& guides, const Sums& sums, const Colours& colours,
                               ROI roi, int nthreads)
{
    std::vector<const ImageBuf*> inputs;
    for (const ImageArg& layer : layers)
        inputs.push_back(&layer.image());
    const std::vector<mcdenoise::LayerTerm> terms = layer_terms(layers.size(), sums, colours);
    std::vector<ImageBuf> results = [&] {
        py::gil_scoped_release release;
        return mcdenoise::denoise_layers(beauty.image(), inputs, guides.guides(), terms, roi,
                                         nthreads);
    }();
    py::object denoised = to_python(std::move(results[0]), beauty);
    py::list out_layers;
    for (size_t i = 1; i < results.size(); ++i)
        out_layers.append(layers[i - 1].to_python(std::move(results[i])));
    return py::make_tuple(denoised, out_layers);
}

/// The library's doc of `denoise_layers` as Python takes it: `sums` and
/// `colours` in place of the C++ `terms`.
std::string python_doc()
{
    std::string doc          = library_doc("denoise_layers");
    const size_t terms       = doc.find("@param terms");
    const size_t after_terms = doc.find("@param", terms + 1);
    if (terms == std::string::npos || after_terms == std::string::npos)
        return doc;
    return doc.substr(0, terms)
           + "@param sums        None (every layer a term of one plain sum), or one int\n"
             "                   per layer: layers with the same int add up to the\n"
             "                   beauty; -1 rebuilds nothing.\n"
             "@param colours     None, or one per layer: the colour (filter) pass it is\n"
             "                   multiplied by in its rebuild, or None for 1; it must\n"
             "                   cover the ROI with the layer's colour channels.\n"
           + doc.substr(after_terms);
}

}  // namespace

void bind_denoise_layers(py::module_& m)
{
    static const std::string layers_doc = python_doc();
    static const std::string denoise_doc
        = "With `layers`: returns (denoised beauty, [denoised layers]).\n\n" + layers_doc;
    m.def("denoise", &denoise_with_layers, denoise_doc.c_str(), py::arg("beauty"), py::kw_only(),
          py::arg("layers"), py::arg("guides") = py::none(), py::arg("sums") = py::none(),
          py::arg("colours") = py::none(), py::arg_v("roi", ROI(), "ROI.All"),
          py::arg("nthreads") = 0);
    m.def("denoise_layers", &denoise_with_layers, layers_doc.c_str(), py::arg("beauty"),
          py::arg("layers"), py::arg("guides") = py::none(), py::arg("sums") = py::none(),
          py::arg("colours") = py::none(), py::arg_v("roi", ROI(), "ROI.All"),
          py::arg("nthreads") = 0);
}

}  // namespace mcdpy
