// guides_arg.cpp: a Python dict of guide images to mcdenoise::Guides.
#include "guides_arg.h"

#include <OpenImageIO/strutil.h>

namespace mcdpy {

const std::map<std::string, const ImageBuf* mcdenoise::Guides::*>& guide_fields()
{
    static const auto fields = [] {
        std::map<std::string, const ImageBuf* mcdenoise::Guides::*> by_name;
        for (const mcdenoise::GuideField& field : mcdenoise::guide_fields)
            by_name.emplace(field.name, field.member);
        return by_name;
    }();
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
