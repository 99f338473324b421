// layer_steps.h: how far `denoise_layers` takes the light layers. Through
// the beauty's own operator alone (the outlier split, the NL-means weights,
// the excess given back: linear in the layers, what the back-off and the
// correction start from, and what the tests check that operator on), or
// all the way (denoise_layers.h).
#pragma once

#include <mcdenoise/denoise_layers.h>

#include <OpenImageIO/imagebuf.h>

#include <vector>

namespace mcdenoise {

/// The steps `denoise_layers_steps` applies to the layers.
enum class LayerSteps {
    /// The beauty's operator alone: no back-off towards each layer's own
    /// values, no correction to add up (`terms` is ignored).
    beauty_operator,
    /// Everything `denoise_layers` does.
    all,
};

/// `denoise_layers` (denoise_layers.h) with the layers taken through
/// `steps`. The beauty's result is `denoise`'s either way.
bool denoise_layers_steps(LayerSteps steps, OIIO::ImageBuf& dst,
                          std::vector<OIIO::ImageBuf>& dst_layers, const OIIO::ImageBuf& beauty,
                          const std::vector<const OIIO::ImageBuf*>& layers, const Guides& guides,
                          const std::vector<LayerTerm>& terms, OIIO::ROI roi, int nthreads);

}  // namespace mcdenoise
