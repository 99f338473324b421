// denoise_network_binding.cpp: `mcdenoise.denoise_network`, the options of
// `NetworkOptions` as keyword arguments (the quality by name).
#include "denoise_network_binding.h"

#include "operation.h"

#include <mcdenoise/denoise_network.h>

#include <cstdint>
#include <string>

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
             "weights): the fields of NetworkOptions.";
}

}  // namespace

void bind_denoise_network(py::module_& m)
{
    static const std::string doc = network_doc();
    m.def(
        "denoise_network",
        [](const ImageArg& beauty, const GuidesArg& guides, const std::string& quality, bool prefilter_guides,
           uint64_t memory_limit, const std::string& weights_dir, ROI roi, int nthreads) -> py::object {
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
            ImageBuf result          = [&] {
                py::gil_scoped_release release;
                return mcd::denoise_network(beauty.image(), guides.guides(), options, roi, nthreads);
            }();
            return to_python(std::move(result), beauty);
        },
        doc.c_str(), py::arg("beauty"), py::arg("guides") = py::none(), py::kw_only(),
        py::arg("quality") = "high", py::arg("prefilter_guides") = true, py::arg("memory_limit") = 0,
        py::arg("weights_dir") = "", py::arg_v("roi", ROI(), "ROI.All"), py::arg("nthreads") = 0);
}

}  // namespace mcdpy
