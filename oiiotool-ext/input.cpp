// input.cpp: image reading with errors that name the file.
#include "input.h"

#include "error.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <OpenImageIO/strutil.h>

namespace mcdtool {

using OIIO::Strutil::fmt::format;

ImageBuf read_image(const std::string& path, std::string_view context)
{
    if (!OIIO::Filesystem::exists(path))
        throw RunError(format("{} : cannot read '{}': no such file", context, path));
    if (OIIO::Filesystem::is_directory(path))
        throw RunError(format("{} : cannot read '{}': it is a directory", context, path));
    ImageBuf image(path);
    if (!image.read(0, 0, true, OIIO::TypeDesc::FLOAT) || image.has_error()) {
        std::string reason = one_line(image.geterror());
        std::string global = one_line(OIIO::geterror());
        throw RunError(format("{} : cannot read '{}': {}", context, path,
                              reason.empty() ? (global.empty() ? "unknown error" : global) : reason));
    }
    if (image.nsubimages() > 1)
        throw RunError(format("{} : '{}' has {} parts (subimages); only single-part files are supported, "
                              "split it with oiiotool first", context, path, image.nsubimages()));
    if (image.deep())
        throw RunError(format("{} : cannot read '{}': deep images are not supported", context, path));
    return image;
}

const ImageBuf& ImageFiles::get(const std::string& path, std::string_view context)
{
    auto found = images_.find(path);
    if (found != images_.end())
        return found->second;
    Timer timer;
    ImageBuf image = read_image(path, context);
    stats_.add_read(timer.seconds());
    return images_.emplace(path, std::move(image)).first->second;
}

}  // namespace mcdtool
