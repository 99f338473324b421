// guides_arg.h: the `guides` argument of the feature-guided filters, from
// Python: a dict (or keyword-style mapping) from the library's Guides field
// names to images (ImageBuf or numpy array), or None for no guides.
#pragma once

#include "image_arg.h"

#include <mcdenoise/features.h>

#include <map>
#include <string>

namespace mcdpy {

/// The guides passed from Python, kept alive for the call.
class GuidesArg {
public:
    GuidesArg() = default;
    /// Reads a dict {field name: image}; raises ValueError for an unknown name.
    explicit GuidesArg(const py::dict& images);
    /// The library's Guides, pointing into the held images.
    const mcdenoise::Guides& guides() const { return guides_; }

private:
    std::map<std::string, ImageArg> images_;
    mcdenoise::Guides guides_;
};

/// The field names of mcdenoise::Guides (`mcdenoise::guide_fields`), with
/// the member each one sets.
const std::map<std::string, const ImageBuf* mcdenoise::Guides::*>& guide_fields();

}  // namespace mcdpy

namespace pybind11::detail {

/// Lets a binding take `const mcdpy::GuidesArg&` for a dict of images or None.
template <> struct type_caster<mcdpy::GuidesArg> {
    PYBIND11_TYPE_CASTER(mcdpy::GuidesArg, const_name("dict[str, OpenImageIO.ImageBuf | numpy.ndarray] | None"));

    bool load(handle source, bool /*convert*/)
    {
        if (source.is_none()) {
            value = mcdpy::GuidesArg();
            return true;
        }
        if (!isinstance<dict>(source))
            return false;
        value = mcdpy::GuidesArg(reinterpret_borrow<dict>(source));
        return true;
    }
};

}  // namespace pybind11::detail
