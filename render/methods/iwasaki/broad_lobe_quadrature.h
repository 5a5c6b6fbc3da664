#pragma once
// The sky's broad lobes by quadrature of the canonical model at the mesh vertices (rungs
// iwasaki_vertex_quadrature and iwasaki_quadrature; docs/research/iwasaki.md, "Broad lobes by quadrature").
// Iwasaki's Eq. 9 factorises a lobe's light into T times a shading integral, which misses by
// 10–17 % where both W and f_s vary over the lobe, and the SDF's one linear boundary cannot hold
// a wide lobe occluded from several sides. So an SG with λ < kBroadLobeSharpness is shaded as the
// reference shades it: the SG-warped grid (core's SgWarpedGrid) of kBroadLobeGrid × 2·kBroadLobeGrid
// cells, each cell's direction weighted by the model's integrand (ClothBsdf::Point::integrand) and
// by its bit from the vertex's visibility mask; the sharper SGs stay with iwasaki. Broad light
// varies slowly over the mesh, so it is taken per vertex and interpolated.
// GLSL: broad_lobe_quadrature.glsl (tests/gpu/iwasaki_parity_test.cpp pins the two).
#include <cstdint>
#include <span>
#include <vector>

#include "core/cloth_bsdf.h"
#include "core/spherical_gaussian.h"
#include "methods/broad_lobe_bits.h"
#include "methods/iwasaki/iwasaki.h"
#include "runtime/visibility_mask.h"
#include "scene/mesh.h"

namespace weft {

// Σ over broad SGs k, cells c: μ_k · w_k · bit · integrand(ω_c, ω_o), w_k = SgWarpedGrid::cell_weight.
// `frame`: the shading frame (facing ω_o); `bits`: the vertex's words (BroadLobeBits::vertex),
// empty for every cell open.
dvec3 broad_lobe_radiance(const ClothBsdf& bsdf, const SurfaceFrame& frame, const dvec3& wo,
                          std::span<const SphericalGaussian> sgs, std::span<const int> slots,
                          std::span<const std::uint32_t> bits);

// The same split into terms (IwasakiTerms: surface and each thread's volume part), for a textured cloth.
IwasakiTerms broad_lobe_terms(const ClothBsdf& bsdf, const SurfaceFrame& frame, const dvec3& wo,
                              std::span<const SphericalGaussian> sgs, std::span<const int> slots,
                              std::span<const std::uint32_t> bits);

// Iwasaki over the SGs with slot −1 only (each SG as iwasaki_radiance shades it, `visibility`
// called with the SG's index in `sgs`).
IwasakiTerms iwasaki_narrow_radiance(const ClothBsdf& bsdf, const WeightingTables& tables, const SurfaceFrame& frame,
                                     const dvec3& wo, std::span<const SphericalGaussian> sgs, std::span<const int> slots,
                                     const IwasakiVisibility* visibility = nullptr);

}  // namespace weft
