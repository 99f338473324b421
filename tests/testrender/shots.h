// shots.h: the animated scenes ("shots") for cross-frame denoising. Each is a
// function of the frame number; the motion repeats every `shot_period`
// frames, so every integer frame is defined.
#pragma once

#include "scene.h"

namespace testrender {

/// Frames after which the shots' motion repeats.
constexpr int shot_period = 48;

/// The stage with nothing moving: only the noise changes from frame to frame.
void shot_static(Scene& s, int frame);
/// The stage seen by a camera trucking left and right, rising as it goes
/// right (parallax between near and far objects, disocclusions at their edges).
void shot_truck(Scene& s, int frame);
/// The stage with a sphere hopping left and right in front of the others,
/// casting a moving shadow on the floor; the camera stays put.
void shot_object(Scene& s, int frame);

}  // namespace testrender
