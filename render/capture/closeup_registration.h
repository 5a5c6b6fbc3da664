#pragma once
// The close-up registered to the weave. Once the spectrum has resolved the lattice
// (thread_counts.h), every pixel lies at a known point of the weave's tile (core/weave_layout.h)
// up to one offset, the tile's phase, and the tile's handedness. Folded into the tile, the frame's
// pixels average hundreds of repeats; the model's resolved weave under the capture's lights
// predicts each bin of the tile as
//   k·S + B_warp ⊙ V_warp + B_weft ⊙ V_weft + g·G
// with S the threads' surface scattering, V_j thread j's volume scattering per unit albedo, G the
// bin's share of gap, k the close-up's exposure, B_j = k·A_j and g what shows through the gaps.
// For one phase that is linear least squares; the phase and handedness leaving the least residual
// register the close-up, and B_warp ÷ B_weft is the threads' albedo ratio channel by channel,
// each thread measured where the weave puts it. A glossy satin's sparse weft is found this way
// where colour clusters fail: its float's highlight is a lightness of its own that no cluster
// tells from a second thread, but the model puts the highlight where the float's tilt faces the
// light and the weft where the weave raises it.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "capture/closeup_scale.h"
#include "capture/fabric_fit.h"
#include "capture/photo_files.h"
#include "capture/response_calibration.h"
#include "capture/thread_counts.h"
#include "core/fabric.h"

namespace weft {

struct CloseupRegistration {
  bool registered = false;
  std::string why;                // when not registered
  glm::ivec2 tile_bins{0};        // the folded tile's bins along s (warp) and t (weft)
  long pixels = 0;                // folded
  glm::dvec2 phase{0.0};          // the tile's offset at the frame's centre, tile units
  bool mirrored = false;          // the weft runs along the image's −(warp turned 90°)
  // The share of the folded tile's variance the model explains at the registered phase, and at
  // the median phase: the weave's pattern must matter (a phase anywhere explaining as much
  // registers nothing).
  double explained = 0, explained_median = 0;
  double exposure = 0;            // k, close-up units per unit of the lights' radiance
  std::array<glm::dvec3, 2> albedo{glm::dvec3(0), glm::dvec3(0)};  // B_j / k
  // Whether k and every B_j came out positive. Broad lobes leave S and V_j alike straight above,
  // and the solve then trades one for the other: the phase and each thread's mean still hold, the
  // albedos do not.
  bool albedo_read = false;
  glm::dvec3 albedo_ratio{1.0};   // warp ÷ weft
  // Each thread's mean value (the close-up's relative units) over the tile's bins that it fills
  // alone, and how many.
  std::array<glm::dvec3, 2> thread_mean{glm::dvec3(0), glm::dvec3(0)};
  std::array<int, 2> inner_bins{0, 0};
  static constexpr double kMinExplained = 0.6;       // of the tile's variance
  static constexpr double kMinPhaseGain = 0.15;      // explained over the median phase's
};

// Registers the close-up `photo` (read through `response`) to the weave of `fabric` (its
// family's layout, its threads' lobes as the photos fitted them) under `lights`, the swatch's warp
// at `turn` in the world as in the last photo. `counts` must be at least a candidate lattice.
CloseupRegistration register_closeup(const Photo& photo, const ResponseModel& response, const CloseupScale& scale,
                                     const ThreadCounts& counts, const Fabric& fabric, const std::vector<FitLight>& lights,
                                     double turn);

}  // namespace weft
