#pragma once
// Methods `sheer` and `sheer_vertex`: the optically thin layer (methods/thin/thin.h) over
// iwasaki (methods/iwasaki/iwasaki.h) with its baked visibility, for sheer fabrics (a fabric's
// optical_thickness τ) in the kiosk:
//   source = (1 − α)·L_iwasaki + Σ_k [V⁺_k·E_k(n)·K_r + V⁻_k·E_k(−n)·K_t],   α = e^{−τ/μ},
// drawn over what lies behind as dst·α + source (premultiplied). L_iwasaki is iwasaki's radiance
// with its SDF-gradient visibility (per SG lobe, the side facing the eye). The single-scatter
// terms take one share per SG and side: on the mesh normal's side, the side the bake cast its
// visibility from, the sigmoid H of the whole SG lobe against the baked SDF at the SG axis (the
// vertex frame's (θ', φ'), widths σ_k and σ_k/cos θ'), divided by the surface's own horizon H
// for the same lobe (the bake counts everything below the horizon as occluded, and the SG's
// clamped-cosine irradiance already leaves that part out), clamped to [0, 1]; on the other side,
// 1 (no visibility is baked there: a curtain's back faces the window it hangs in front of).
// Mirrored by sheer.glsl; tests/gpu/sheer_parity_test.cpp pins the two.
#include <optional>
#include <span>
#include <vector>

#include "core/cloth_bsdf.h"
#include "core/spherical_gaussian.h"
#include "methods/iwasaki/iwasaki.h"
#include "methods/thin/thin.h"
#include "runtime/sigmoid_gain_table.h"
#include "runtime/weighting_tables.h"

namespace weft {

// Share of SG `g`'s light reaching the side of the mesh normal at a point with vertex frame
// `mesh_frame` (the mesh's normal and warp, unflipped), from the baked SDF there at the SG axis
// (`sdf` = (d, ∂d/∂θ', ∂d/∂φ'), SgVisibility's values blended over the corners). `kappa`: the
// baked sigmoid gains (as iwasaki's H), or null for the closed-form linear H.
double sheer_sdf_share(const SphericalGaussian& g, const SurfaceFrame& mesh_frame, const dvec3& sdf,
                       const SigmoidGainTable* kappa);

// One cloth point: `mesh_frame` as above; `visibility` (or null) is iwasaki's for the reflection
// (built on the frame turned to face ω_o, as iwasaki_radiance's callers do) and `mesh_side`
// one sheer_sdf_share per SG (empty: unoccluded).
ThinShade sheer_radiance(const ClothBsdf& bsdf, const WeightingTables& tables, const ThinParams& layer,
                         const SurfaceFrame& mesh_frame, const dvec3& wo, std::span<const SphericalGaussian> sgs,
                         const IwasakiVisibility* visibility = nullptr, std::span<const double> mesh_side = {});

}  // namespace weft
