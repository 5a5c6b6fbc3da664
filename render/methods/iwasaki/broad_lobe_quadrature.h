#pragma once
// The sky's broad lobes by quadrature of the canonical model at the mesh vertices (rungs
// iwasaki_vertex_quadrature and iwasaki_quadrature; IWASAKI.md, "Broad lobes by quadrature").
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
#include "methods/iwasaki/iwasaki.h"
#include "runtime/visibility_mask.h"
#include "scene/mesh.h"

namespace weft {

inline constexpr double kBroadLobeSharpness = 4.0;  // λ_b: an SG with λ < λ_b is broad
inline constexpr int kBroadLobeGrid = 8;            // M: M × 2M cells per broad SG
// Broad SGs beyond this many (the sharpest of them) stay with iwasaki; a 10-SG sky fit holds 2–5.
inline constexpr int kMaxBroadLobes = 4;
inline constexpr int kBroadLobeCells = 2 * kBroadLobeGrid * kBroadLobeGrid;
inline constexpr int kBroadLobeWordsPerSg = (kBroadLobeCells + 31) / 32;
inline constexpr int kBroadLobeWordsPerVertex = kMaxBroadLobes * kBroadLobeWordsPerSg;

// Per SG of a lighting: its slot among the broad lobes (0 … kMaxBroadLobes − 1, broadest first),
// or −1 for an SG iwasaki shades.
std::vector<int> broad_lobe_slots(std::span<const SphericalGaussian> sgs);

// Per vertex and broad slot, one bit per grid cell (cell c = i·2M + j of SgWarpedGrid): the
// cell's direction open in the vertex's visibility mask. Directions below the vertex's surface
// (the mask's hemisphere) are left open: the integrand is zero there on the side the mask
// covers, and from behind the mask says nothing about that side.
struct BroadLobeBits {
  size_t vertices = 0;
  std::vector<std::uint32_t> words;  // [vertex][slot·kBroadLobeWordsPerSg + c/32], bit c mod 32
  std::span<const std::uint32_t> vertex(size_t v) const {
    return std::span<const std::uint32_t>(words).subspan(v * kBroadLobeWordsPerVertex, kBroadLobeWordsPerVertex);
  }
  // Every cell open (no mask: unoccluded).
  static BroadLobeBits all_open(size_t vertices);
  // `mesh`: the mask's object (the vertex frames the bake cast from: normal + warp).
  static BroadLobeBits compute(const VisibilityMask& mask, const TriangleMesh& mesh, std::span<const SphericalGaussian> sgs);
};

// Σ over broad SGs k, cells c: μ_k · w_k · bit · integrand(ω_c, ω_o), w_k = SgWarpedGrid::cell_weight.
// `frame`: the shading frame (facing ω_o); `bits`: the vertex's words (BroadLobeBits::vertex),
// empty for every cell open.
dvec3 broad_lobe_radiance(const ClothBsdf& bsdf, const SurfaceFrame& frame, const dvec3& wo,
                          std::span<const SphericalGaussian> sgs, std::span<const int> slots,
                          std::span<const std::uint32_t> bits);

// Iwasaki over the SGs with slot −1 only (each SG as iwasaki_radiance shades it, `visibility`
// called with the SG's index in `sgs`).
IwasakiTerms iwasaki_narrow_radiance(const ClothBsdf& bsdf, const WeightingTables& tables, const SurfaceFrame& frame,
                                     const dvec3& wo, std::span<const SphericalGaussian> sgs, std::span<const int> slots,
                                     const IwasakiVisibility* visibility = nullptr);

}  // namespace weft
