// module.cpp: the compiled module mcdenoise._mcdenoise: the library's filters,
// metrics and named defaults, mcdtool's frame runner, and the exceptions they
// raise.
#include "defaults.h"
#include "driver.h"
#include "operation.h"
#include "operations.h"
#include "sequence_metrics.h"

#include "oiiotool-ext/error.h"

#include <mcdenoise/features.h>
#include <mcdenoise/metrics.h>
#include <mcdenoise/version.h>

#include <stdexcept>
#include <string>

namespace mcdpy {

namespace {

/// What raise_library_error throws; becomes mcdenoise.Error.
struct LibraryError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// The ImageComparison record of compare_images, fields as in C++.
void bind_comparison(py::module_& m)
{
    using mcdenoise::ImageComparison;
    py::class_<ImageComparison>(m, "ImageComparison", "Every metric of one comparison (see compare_images).")
        .def_readonly("rel_mse", &ImageComparison::rel_mse)
        .def_readonly("mse", &ImageComparison::mse)
        .def_readonly("psnr", &ImageComparison::psnr)
        .def_readonly("ssim", &ImageComparison::ssim)
        .def_readonly("pixels", &ImageComparison::pixels)
        .def_readonly("nonfinite", &ImageComparison::nonfinite)
        .def_readonly("ok", &ImageComparison::ok)
        .def_readonly("error", &ImageComparison::error)
        .def("__repr__", [](const ImageComparison& c) {
            return py::str("ImageComparison(rel_mse={}, mse={}, psnr={}, ssim={}, pixels={}, nonfinite={})")
                .format(c.rel_mse, c.mse, c.psnr, c.ssim, c.pixels, c.nonfinite);
        });
}

/// The feature fall-offs of the feature-guided filters, fields as in C++.
void bind_feature_sigmas(py::module_& m)
{
    using mcdenoise::FeatureSigmas;
    const FeatureSigmas defaults;
    py::class_<FeatureSigmas>(m, "FeatureSigmas",
                              "How fast a neighbour's weight falls with each feature difference "
                              "(see features.h); a sigma <= 0 leaves that feature out.")
        .def(py::init([](float albedo, float normal, float depth) {
                 return FeatureSigmas{ albedo, normal, depth };
             }),
             py::arg("albedo") = defaults.albedo, py::arg("normal") = defaults.normal,
             py::arg("depth") = defaults.depth)
        .def_readwrite("albedo", &FeatureSigmas::albedo)
        .def_readwrite("normal", &FeatureSigmas::normal)
        .def_readwrite("depth", &FeatureSigmas::depth)
        .def("__repr__", [](const FeatureSigmas& s) {
            return py::str("FeatureSigmas(albedo={:.7g}, normal={:.7g}, depth={:.7g})")
                .format(s.albedo, s.normal, s.depth);
        });
}

}  // namespace

void raise_library_error(const std::string& message) { throw LibraryError(message); }

}  // namespace mcdpy

PYBIND11_MODULE(_mcdenoise, m)
{
    namespace py = pybind11;
    // OpenImageIO registers ImageBuf and ROI in pybind11's shared registry;
    // it must be imported before the first def that names them.
    py::module_::import("OpenImageIO");
    m.doc() = "libmcdenoise's filters and metrics, and mcdtool's frame runner.";
    // the loaded library's version (mcdenoise/version.h)
    m.attr("__version__") = mcdenoise::version();
    m.def("version", [] { return std::string(mcdenoise::version()); }, mcdpy::library_doc("version"));
    m.def("version_number", &mcdenoise::version_number, mcdpy::library_doc("version_number"));

    static py::exception<mcdpy::LibraryError> error(m, "Error", PyExc_RuntimeError);
    static py::exception<mcdtool::UsageError> usage_error(m, "UsageError", PyExc_ValueError);
    py::register_exception_translator([](std::exception_ptr raised) {
        try {
            if (raised)
                std::rethrow_exception(raised);
        } catch (const mcdpy::LibraryError& e) {
            error(e.what());
        } catch (const mcdtool::RunError& e) {
            error(e.what());
        } catch (const mcdtool::UsageError& e) {
            usage_error(e.what());
        }
    });

    mcdpy::bind_comparison(m);
    mcdpy::bind_feature_sigmas(m);
    mcdpy::bind_operations(m);
    mcdpy::bind_sequence_metrics(m);
    mcdpy::bind_defaults(m);
    mcdpy::bind_driver(m);
}
