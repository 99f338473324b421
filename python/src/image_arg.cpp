// image_arg.cpp: numpy arrays to float ImageBufs and results back.
#include "image_arg.h"

#include <OpenImageIO/strutil.h>

namespace mcdpy {

namespace {

/// A C-contiguous float32 view of `array` (converted if needed).
using FloatArray = py::array_t<float, py::array::c_style | py::array::forcecast>;

}  // namespace

ImageArg::ImageArg(const py::array& array) : from_numpy_(true), ndim_(int(array.ndim()))
{
    if (ndim_ != 2 && ndim_ != 3)
        throw py::value_error(OIIO::Strutil::fmt::format(
            "expected an image array of shape (H, W) or (H, W, C), got {} dimensions", ndim_));
    FloatArray pixels = FloatArray::ensure(array);
    if (!pixels)
        throw py::type_error("expected an image array of real numbers");
    int height = int(pixels.shape(0));
    int width = int(pixels.shape(1));
    int channels = ndim_ == 3 ? int(pixels.shape(2)) : 1;
    if (height < 1 || width < 1 || channels < 1)
        throw py::value_error(OIIO::Strutil::fmt::format(
            "expected a non-empty image array, got shape ({}, {}, {})", height, width, channels));
    auto image = std::make_shared<ImageBuf>(OIIO::ImageSpec(width, height, channels, OIIO::TypeDesc::FLOAT));
    image->set_pixels(image->roi(), OIIO::TypeDesc::FLOAT, pixels.data());
    owned_ = image;
    image_ = owned_.get();
}

py::object ImageArg::to_python(ImageBuf&& result) const
{
    if (!from_numpy_)
        return py::cast(std::move(result));
    const OIIO::ImageSpec& spec = result.spec();
    std::vector<py::ssize_t> shape = { spec.height, spec.width };
    if (ndim_ == 3 || spec.nchannels != 1)
        shape.push_back(spec.nchannels);
    FloatArray pixels(shape);
    if (!result.get_pixels(result.roi(), OIIO::TypeDesc::FLOAT, pixels.mutable_data()))
        throw std::runtime_error(result.geterror());
    return std::move(pixels);
}

}  // namespace mcdpy
