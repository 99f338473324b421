// image_arg.h: an image argument of a binding: an OpenImageIO.ImageBuf
// (used in place, the type shared with python3-openimageio through pybind11's
// common registry) or a numpy array of shape (H, W) or (H, W, C), copied once
// to a float ImageBuf. Results go back in the kind the beauty came in.
#pragma once

#include <OpenImageIO/imagebuf.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <memory>

namespace mcdpy {

namespace py = pybind11;
using OIIO::ImageBuf;

/// An image passed from Python.
class ImageArg {
public:
    ImageArg() = default;
    /// Borrows the ImageBuf held by a Python OpenImageIO.ImageBuf.
    explicit ImageArg(const ImageBuf& borrowed) : image_(&borrowed) {}
    /// Copies a numpy array (H, W) or (H, W, C) of any real type to float.
    explicit ImageArg(const py::array& array);

    /// The image to filter.
    const ImageBuf& image() const { return *image_; }
    /// True if it came as a numpy array.
    bool from_numpy() const { return from_numpy_; }
    /// `result` as the caller's kind: a numpy float32 array with this
    /// argument's number of dimensions, or an OpenImageIO.ImageBuf.
    py::object to_python(ImageBuf&& result) const;

private:
    std::shared_ptr<const ImageBuf> owned_;  ///< the copy of a numpy array
    const ImageBuf* image_ = nullptr;
    bool from_numpy_ = false;
    int ndim_ = 3;
};

}  // namespace mcdpy

namespace pybind11::detail {

/// Lets a binding take `const mcdpy::ImageArg&` for an ImageBuf or array.
template <> struct type_caster<mcdpy::ImageArg> {
    PYBIND11_TYPE_CASTER(mcdpy::ImageArg, const_name("OpenImageIO.ImageBuf | numpy.ndarray"));

    bool load(handle source, bool /*convert*/)
    {
        make_caster<OIIO::ImageBuf> image_caster;
        if (image_caster.load(source, false)) {
            value = mcdpy::ImageArg(cast_op<const OIIO::ImageBuf&>(image_caster));
            return true;
        }
        if (!isinstance<array>(source))
            return false;
        value = mcdpy::ImageArg(reinterpret_borrow<array>(source));
        return true;
    }
};

}  // namespace pybind11::detail
