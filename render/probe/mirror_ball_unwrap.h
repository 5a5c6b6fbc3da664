#pragma once
// Merged mirror-ball photograph -> equirect environment map in the world frame (docs/design.md §3),
// ready for the SG fit. Every texel averages 3×3 reflected directions spread over its extent,
// each looked up (bilinear) where the ball reflects it (mirror_ball.h). Texels in the masked
// cap behind the ball (which the ball does not show usefully) take the solid-angle weighted
// mean of the 10° ring of valid texels around the cap: the best guess a single ball allows.
#include "camera/hdr_merge.h"
#include "camera/mirror_ball.h"
#include "lighting/env_map.h"

namespace weft {

EnvMap unwrap_mirror_ball(const HdrImage& image, const MirrorBall& ball, int width, int height);

}  // namespace weft
