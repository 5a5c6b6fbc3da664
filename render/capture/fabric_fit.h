#pragma once
// Fitting a fabric to the swatch's rectified pixels (docs/design.md §2 at the fabric level, a flat
// swatch, unoccluded): for each preset's weave (its tangent curves, coverages and η), each thread's
// albedo A (RGB), k_d, γ_s and γ_v by Levenberg–Marquardt (Eigen's), bounded through a logistic
// map onto the presets' ranges, under a Huber loss on relative residuals; the preset whose weave
// leaves the smallest cost is the weave family.
//
// The evaluation is the model itself, arranged for speed: per observation, light and tangent
// sample, everything but the two Gaussians N(θ_h; γ_s) and N(θ_h; γ_v) is fixed by the weave and
// the geometry, so it is computed once per preset; A and k_d enter linearly.
#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

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
};

struct FabricFitOptions {
  int tangent_samples = 16;  // N_j per thread in the fit
  std::function<void(double)> progress;
};

// Throws std::invalid_argument when there are no observations, lights or presets.
FabricFit fit_fabric(const std::vector<SwatchObservation>& observations, const std::vector<FitLight>& lights,
                     const std::vector<Fabric>& presets, const FabricFitOptions& options = {});

// The same model, straight: the swatch's radiance at one view (for the report's fitted render).
glm::dvec3 swatch_radiance(const Fabric& fabric, double turn, const glm::dvec3& wo, const std::vector<FitLight>& lights,
                           int tangent_samples = 16);

}  // namespace weft
