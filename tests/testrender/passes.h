// passes.h: the light passes (Blender Cycles' convention): what one camera
// sample contributes to each, and how a pixel's sums become the passes, so
// that per pixel
//   beauty = DiffCol (DiffDir + DiffInd) + GlossCol (GlossDir + GlossInd)
//          + TransCol (TransDir + TransInd) + Emit + Env.
#pragma once

#include "math.h"

#include <string>
#include <vector>

namespace testrender {

/// The scattering classes of the first hit: which pass a path's light goes to.
enum Lobe { diffuse_lobe = 0, glossy_lobe = 1, transmission_lobe = 2, lobe_count = 3 };

/// What one camera sample adds to the passes. `direct` and `indirect` are
/// radiance (not yet divided by the colour); the first hit's lobe decides
/// the class: light reaching the camera after one scattering at the first
/// hit is direct, after more it is indirect.
struct SamplePasses {
    Vec3 colour[lobe_count];    ///< the first hit's lobe weights
    Vec3 direct[lobe_count];
    Vec3 indirect[lobe_count];
    Vec3 emit;  ///< an emitter seen directly
    Vec3 env;   ///< the background seen directly (0 with a transparent film)
};

/// The number of pass channels and their names in file order:
/// DiffDir.R,G,B, DiffInd, DiffCol, GlossDir, GlossInd, GlossCol, TransDir,
/// TransInd, TransCol, Emit, Env (each .R,.G,.B).
constexpr int pass_channels = 33;
const std::vector<std::string>& pass_channel_names();

/// A pixel's passes in the order of `pass_channel_names` from the sums of
/// its `spp` samples' SamplePasses: Col is the mean colour; Dir and Ind are
/// the mean radiance divided by Col, per channel. Where a colour channel is
/// 0 but its class received light (no built-in material does that), the
/// light is added to Emit, so the sum above still holds.
void finish_passes(const SamplePasses& sums, int spp, float* out);

}  // namespace testrender
