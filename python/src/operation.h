// operation.h: binding one library operation from its value form. Every
// `const ImageBuf&` argument becomes an ImageArg (ImageBuf or numpy array)
// and `const Guides&` a dict of them (GuidesArg); `roi` and `nthreads` are
// appended with the library's defaults; the GIL is released while the
// library runs; a result with an error raises mcdenoise.Error carrying the
// library's message.
#pragma once

#include "guides_arg.h"
#include "image_arg.h"
#include "library_docs.h"

#include <mcdenoise/metrics.h>

#include <OpenImageIO/imagebuf.h>

#include <pybind11/pybind11.h>

#include <string>
#include <utility>

namespace mcdpy {

using OIIO::ROI;

/// The Python-side type of a library argument of type T.
template <typename T> struct PyArg {
    using type = T;
};
template <> struct PyArg<const ImageBuf&> {
    using type = const ImageArg&;
};
template <> struct PyArg<const mcdenoise::Guides&> {
    using type = const GuidesArg&;
};

/// The library-side value of a Python argument.
template <typename T> const T& unwrap(const T& value) { return value; }
inline const ImageBuf& unwrap(const ImageArg& image) { return image.image(); }
inline const mcdenoise::Guides& unwrap(const GuidesArg& guides) { return guides.guides(); }

/// The library's doc comment of `name` (empty if it has none).
inline const char* library_doc(const std::string& name)
{
    auto found = library_docs().find(name);
    return found == library_docs().end() ? "" : found->second;
}

/// Raises mcdenoise.Error with `message` (defined in module.cpp).
[[noreturn]] void raise_library_error(const std::string& message);

/// A result as Python sees it: images in the kind `first` came in, after
/// raising the library's error if it has one (images, comparisons); anything
/// else as is.
inline py::object to_python(ImageBuf&& result, const ImageArg& first)
{
    if (result.has_error())
        raise_library_error(result.geterror());
    return first.to_python(std::move(result));
}
inline py::object to_python(mcdenoise::ImageComparison&& comparison, const ImageArg&)
{
    if (!comparison.ok)
        raise_library_error(comparison.error);
    return py::cast(std::move(comparison));
}
template <typename R> py::object to_python(R&& result, const ImageArg&)
{
    return py::cast(std::forward<R>(result));
}

/// Binds `function` (the value form of a library operation taking an image
/// first, then `Args...`, the last two being `ROI roi, int nthreads`) as
/// `name`, with the library's doc comment. `args` names every argument before
/// `roi`, with defaults where the library has them.
template <typename R, typename... Args, typename... PyArgs>
void def_operation(py::module_& module, const char* name, R (*function)(const ImageBuf&, Args...),
                   PyArgs&&... args)
{
    module.def(
        name,
        [function](const ImageArg& first, typename PyArg<Args>::type... rest) -> py::object {
            R result = [&] {
                py::gil_scoped_release release;
                return function(first.image(), unwrap(rest)...);
            }();
            return to_python(std::move(result), first);
        },
        library_doc(name), std::forward<PyArgs>(args)..., py::arg_v("roi", ROI(), "ROI.All"),
        py::arg("nthreads") = 0);
}

}  // namespace mcdpy
