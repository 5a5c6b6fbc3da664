#pragma once
// A cloth's normal map applied as seed 002 does for anisotropic cloth: the shading normal is
// perturbed AND the thread frame is turned with it, by the one rotation that takes n to the
// perturbed n' (the smallest, about n × n'), so the warp and weft stay in the perturbed surface
// and the canonical model shades in that frame. Plain normal mapping (n' with the old warp made
// orthogonal to it) would swing the threads' azimuth wherever the bump tilts across them.
// Mirrored by shaders/normal_map_frame.glsl (the parity test pins the two).
#include "core/microcylinder.h"

namespace weft {

// A normal map texel (its RGB in [0, 1], stored linearly) as a unit tangent-space normal: glTF's
// (2c − 1) with x and y multiplied by `scale` (normalTexture.scale), renormalized (a mip level's
// average of unit normals is shorter than 1), z kept at least kMinNormalMapZ so n' never leaves
// the hemisphere of n. An 8-bit map cannot hold 0.5: its flat codes 127 and 128 read ±1/255, a
// tilt a sharp highlight shows, so x and y are moved towards 0 by that half step (continuously,
// ±1 kept) and a painted flat map is flat.
inline constexpr double kNormalMapHalfStep = 1.0 / 255.0;
dvec3 tangent_space_normal(dvec3 texel, double scale);
inline constexpr double kMinNormalMapZ = 1e-3;

// The frame `frame` (n, u along the warp, v = n × u) turned by the rotation that takes n to
// n' = t.x·u + t.y·v + t.z·n, for a unit tangent-space normal t (x along the warp = the map's +X
// along +u; y along v = n × u, the map's +Y, which is −v in glTF's UVs, for an unmirrored layout).
SurfaceFrame normal_mapped_frame(const SurfaceFrame& frame, dvec3 t);

}  // namespace weft
