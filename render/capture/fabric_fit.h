#pragma once
// Fitting a fabric to the swatch's rectified pixels (docs/design.md §2 at the fabric level, a flat
// swatch, unoccluded): for each preset's weave (its tangent curves, coverages and η), each thread's
// albedo A (RGB), k_d, γ_s and γ_v by Levenberg–Marquardt (Eigen's), bounded through a logistic
// map onto the presets' ranges, under a Huber loss on relative residuals; the preset whose weave
// leaves the smallest cost is the weave family.
//
// The evaluation is the model itself, arranged for speed: per observation, light and tangent
// sample, everything but the two Gaussians N(θ_h; γ_s) and N(θ_h; γ_v) is fixed by the weave and
// the geometry, so it is computed once per preset; A and k_d enter linearly. A close-up adds the
// ratio of the threads' resolved mean radiances straight above: each thread's term of the
// fabric-level model over its coverage a_j (the resolved weave averages to the fabric level).
#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "capture/closeup_shot.h"
#include "core/fabric.h"

namespace weft {

// One cell of the swatch in one photo: its mean value in the lighting's units, where it was seen
// from, and how the swatch lay.
struct SwatchObservation {
  glm::dvec3 value{0.0};
  glm::dvec3 wo{0, 0, 1};  // unit, toward the camera, world (+Z the swatch's normal)
  double turn = 0;         // warp angle in world, radians
  int photo = 0;
};

// A directional light: power ∫L dω along a unit direction above the swatch.
struct FitLight {
  glm::dvec3 direction;
  glm::dvec3 power;
};

// The close-up (capture/closeup_shot.h): its splits into two colour clusters, not yet told apart
// as warp and weft, seen from straight above with the swatch at `turn`.
struct CloseupObservation {
  std::vector<CloseupSplit> splits;
  double turn = 0;
  // The swatch's mean straight above in the photos' units (CloseupClusters::level), where the
  // close-up's tag gives it: a view the turned photos do not have, which tells a thread's
  // albedo from the shape of its volume lobe better than their one elevation does.
  std::optional<glm::dvec3> level;
  // The close-up registered to the chosen family's weave (capture/closeup_registration.h), given
  // that family's fit to the photos, or nothing where it does not register. Taken before the
  // splits: it tells the threads apart by where they lie, not by their colours.
  struct Registered {
    std::array<glm::dvec3, 2> mean;    // each thread's mean value where the weave puts it (warp, weft)
    // Each thread's albedo under the fitted lobes, where the registration could read it: a start
    // for the refit.
    std::optional<std::array<glm::dvec3, 2>> albedo;
    double explained = 0;              // the share of the folded tile the weave's model explains
  };
  std::function<std::optional<Registered>(const Fabric& fitted)> registered;
};

// What the fit made of the close-up.
struct CloseupFit {
  // Whether the fit kept it: not when the fabric cannot match both the photos and the close-up
  // (the fit without it stands, and `rejected` says why).
  bool used = false;
  // The split on colour alone does not separate: the close-up shows one hue, and the threads'
  // chromaticities are tied; when the split with lightness does not either, their lightness too.
  bool one_colour = false;
  bool one_lightness = false;
  std::string rejected;
  bool registered = false;         // the threads' means from the registered close-up, not a split
  int split = -1;                  // the split taken (CloseupObservation::splits)
  int warp_cluster = 0;            // its cluster taken as the warp (the other is the weft)
  double warp_share = 0;           // that cluster's share, against the family's a_1 / (a_1 + a_2)
  glm::dvec3 measured_ratio{1.0};  // warp ÷ weft mean radiance per channel, from the close-up
  glm::dvec3 fitted_ratio{1.0};    // the same of the fitted fabric
  std::optional<glm::dvec3> measured_level, fitted_level;  // the swatch's mean straight above
};

struct ThreadUncertainty {
  glm::dvec3 albedo{0.0};
  double kd = 0, gamma_s = 0, gamma_v = 0;  // γ in radians
};

struct FabricFit {
  Fabric fabric;                   // the preset's weave with the fitted threads
  std::string preset;              // the weave family
  double rms_relative = 0;         // RMS of (model − photo) / photo over every observation
  double cost = 0;                 // the robust cost the family was chosen by
  std::array<ThreadUncertainty, 2> sigma;  // 1σ from the Jacobian at the optimum
  std::vector<std::pair<std::string, double>> family_costs;  // every preset tried, its cost
  int iterations = 0;
  std::optional<CloseupFit> closeup;
};

struct FabricFitOptions {
  // N_j per thread: every family is tried with `tangent_samples`, the chosen one fitted again with
  // `final_tangent_samples` (a glossy float's highlight is a few degrees of tilt wide, and a coarse
  // quadrature of its curve misses or doubles it: a charmeuse's weft came back ΔE 3.3 off at 32,
  // 1.2 at 48 and 64; 48 keeps its fit under a minute).
  int tangent_samples = 16;
  int final_tangent_samples = 48;
  std::function<void(double)> progress;
};

// Throws std::invalid_argument when there are no observations, lights or presets. With a
// close-up, the family is still chosen by the turned photos, then fitted again with
// `final_tangent_samples`; that fit then also matches the close-up's ratio of the threads' means:
// where the close-up registers to the family's weave, the means read where the weave puts each
// thread (from the photos' optimum and, where that does not hold them, again from the albedos the
// registration read); otherwise from the first split whose clusters cover the family's coverages within
// kCloseupShare (the warp is the cluster nearer a_1/(a_1 + a_2), or for even coverages the one
// whose ratio the family's first fit comes closer to). The threads' chromaticities are tied when
// the split on colour alone does not separate (one hue; registered, only if its albedos agree).
// The close-up is dropped when that fit misses the ratio by more than kCloseupMisses in a
// channel's log, or the photos by more than kCloseupCostGrowth times their cost without it
// (kRegisteredCostGrowth for registered means): clusters can be other than the threads (a glossy
// float's highlight makes a cluster of its own); registered means are measured to about 1 %, and
// the photos' own optimum takes up the ball's lighting error, so holding them costs more.
inline constexpr double kCloseupMisses = 0.2;
inline constexpr double kCloseupShare = 0.15;
inline constexpr double kCloseupCostGrowth = 2.0;
inline constexpr double kRegisteredCostGrowth = 4.0;
FabricFit fit_fabric(const std::vector<SwatchObservation>& observations, const std::vector<FitLight>& lights,
                     const std::vector<Fabric>& presets, const FabricFitOptions& options = {},
                     const std::optional<CloseupObservation>& closeup = std::nullopt);

// The same model, straight: the swatch's radiance at one view (for the report's fitted render).
glm::dvec3 swatch_radiance(const Fabric& fabric, double turn, const glm::dvec3& wo, const std::vector<FitLight>& lights,
                           int tangent_samples = 16);

}  // namespace weft
