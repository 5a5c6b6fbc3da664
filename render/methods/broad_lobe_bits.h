#pragma once
// Which SGs of a lighting are the sky's broad lobes, and per vertex the bits of their quadrature
// cells that the vertex's visibility mask leaves open: what a lighting change computes on the CPU
// for the rungs that shade the broad lobes by quadrature (methods/iwasaki/broad_lobe_quadrature.h,
// docs/research/iwasaki.md "Broad lobes by quadrature"), carried in SgVisibility (methods/sg_visibility.h).
#include <cstdint>
#include <span>
#include <vector>

#include "core/microcylinder.h"
#include "core/spherical_gaussian.h"
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

}  // namespace weft
