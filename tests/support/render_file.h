// render_file.h: a testrender EXR split into the beauty and the guide
// images the filters take, and the report's filters as named callables, for
// the quality tests and the quality study.
#pragma once

#include <mcdenoise/features.h>

#include <OpenImageIO/imagebuf.h>

#include <functional>
#include <string>
#include <vector>

namespace testimg {

/// The beauty and guides of one testrender file.
struct Render {
    OIIO::ImageBuf beauty, object_id, reflect_id, normal, depth, albedo;
    OIIO::ImageBuf variance, half_a, half_b;
    OIIO::ImageBuf motion;  ///< motion.X,Y,Z,W (not among `guides()`)
    std::string error;  ///< set when the file could not be read

    /// Every guide of this render, for the feature-guided filters.
    mcdenoise::Guides guides() const
    {
        return { &object_id, &normal, &depth, &albedo, &variance, &half_a, &half_b };
    }
};

/// Read `path` (testrender channel names: R,G,B, id, reflid, N.*, Z, albedo.*,
/// var.*, A.*, B.*, motion.*).
Render read_render(const std::string& path);

/// A filter of the report applied to a render: returns the filtered beauty.
using RenderFilter = std::function<OIIO::ImageBuf(const Render&)>;

/// A named filter configuration ("object_median 7", "chain" ...).
struct NamedFilter {
    std::string name;
    RenderFilter run;
};

/// Every filter of the report at sizes 3 and 7 (dof at 10 levels, focus 0),
/// then the report's best chain (object_median 7 then gaussian 3).
std::vector<NamedFilter> report_filters();

/// The report's best chain: object_median 7 then gaussian 3.
OIIO::ImageBuf best_chain(const Render& r);

/// relMSE of `result` against `reference` over the pixels where `mask`
/// (one channel, same data window) is non-zero; the library's relMSE on
/// images that agree elsewhere, rescaled to the masked count.
double masked_rel_mse(const OIIO::ImageBuf& result, const OIIO::ImageBuf& reference,
                      const OIIO::ImageBuf& mask);

/// A one-channel mask: 1 where the `size` x `size` window (clipped) around
/// the pixel holds a single object id, 0 near object edges.
OIIO::ImageBuf single_object_pixels(const OIIO::ImageBuf& object_id, int size);

}  // namespace testimg
