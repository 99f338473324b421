// guides_arg.cpp: a Python dict of guide images to mcdenoise::Guides.
#include "guides_arg.h"

#include <OpenImageIO/strutil.h>

namespace mcdpy {

const std::map<std::string, const ImageBuf* mcdenoise::Guides::*>& guide_fields()
{
    using G = mcdenoise::Guides;
    static const std::map<std::string, const ImageBuf* G::*> fields = {
        { "object_id", &G::object_id }, { "normal", &G::normal },     { "depth", &G::depth },
        { "albedo", &G::albedo },       { "variance", &G::variance }, { "half_a", &G::half_a },
        { "half_b", &G::half_b },       { "motion", &G::motion },
    };
    return fields;
}

GuidesArg::GuidesArg(const py::dict& images)
{
    std::vector<std::string> names;
    for (const auto& field : guide_fields())
        names.push_back(field.first);
    for (const auto& item : images) {
        std::string name = py::str(item.first);
        auto field = guide_fields().find(name);
        if (field == guide_fields().end())
            throw py::value_error(OIIO::Strutil::fmt::format("guides: unknown guide '{}' (one of: {})", name,
                                                             OIIO::Strutil::join(names, ", ")));
        if (item.second.is_none())
            continue;
        py::detail::make_caster<ImageArg> image;
        if (!image.load(item.second, true))
            throw py::type_error(OIIO::Strutil::fmt::format(
                "guides: '{}' must be an OpenImageIO.ImageBuf or a numpy array", name));
        images_[name] = py::detail::cast_op<ImageArg&&>(std::move(image));
        guides_.*(field->second) = &images_[name].image();
    }
}

}  // namespace mcdpy
