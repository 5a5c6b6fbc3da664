#include "methods/weave/weave_lights.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

#include "methods/sg_lights.h"
#include "methods/sg_visibility.h"

namespace weft {

namespace {
// Φ(x), the standard normal's CDF.
double normal_cdf(double x) { return 0.5 * std::erfc(-x / std::numbers::sqrt2); }

// An SG with axis `axis`, sharpness `sharpness` and the power `power` (sg_power's, per channel).
SphericalGaussian with_power(const dvec3& axis, double sharpness, const dvec3& power) {
  SphericalGaussian unit{axis, sharpness, dvec3(1.0)};
  return SphericalGaussian{axis, sharpness, power / sg_power(unit)};
}
}  // namespace

SgLighting weave_lights(const SgLighting& sgs, int max_lights) {
  // Broadest first, while each split still fits.
  std::vector<size_t> order(sgs.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return sgs[a].sharpness < sgs[b].sharpness; });
  std::vector<bool> split(sgs.size(), false);
  int count = int(sgs.size());
  for (size_t i : order) {
    if (!(sgs[i].sharpness < kWeaveSplitSharpness) || count + kWeaveSplitParts - 1 > max_lights) break;
    split[i] = true;
    count += kWeaveSplitParts - 1;
  }
  SgLighting out;
  out.reserve(size_t(count));
  for (size_t i = 0; i < sgs.size(); ++i) {
    const SphericalGaussian& g = sgs[i];
    if (!split[i]) {
      out.push_back(g);
      continue;
    }
    const dvec3 xi = glm::normalize(g.axis);
    const dvec3 part_power = sg_power(g) / double(kWeaveSplitParts);
    const double w0 = 1.0 / kWeaveSplitParts, lambda = 2.0 * g.sharpness;
    const double beta = std::min(1.0 / std::sqrt((1.0 - w0) * g.sharpness), 0.5 * std::numbers::pi);
    const dvec3 e1 = glm::normalize(glm::cross(xi, std::abs(xi.x) < 0.9 ? dvec3(1, 0, 0) : dvec3(0, 1, 0)));
    const dvec3 e2 = glm::cross(xi, e1);
    out.push_back(with_power(xi, lambda, part_power));
    for (int r = 0; r < kWeaveSplitParts - 1; ++r) {
      const double phi = 2.0 * std::numbers::pi * r / (kWeaveSplitParts - 1);
      const dvec3 axis = std::cos(beta) * xi + std::sin(beta) * (std::cos(phi) * e1 + std::sin(phi) * e2);
      out.push_back(with_power(glm::normalize(axis), lambda, part_power));
    }
  }
  return out;
}

std::vector<float> weave_light_visibility(const VisibilityMask* mask, const ObjectVisibility* sdf, const TriangleMesh& mesh,
                                          const SgLighting& lights) {
  if (!mask && !sdf) return {};
  const size_t n = lights.size();
  if (mask) {
    const SgVisibility v = SgVisibility::from_mask(*mask, mesh, lights);
    std::vector<float> out(v.vertices * n);
    for (size_t i = 0; i < out.size(); ++i) out[i] = v.values[3 * i];
    return out;
  }
  const SgVisibility v = SgVisibility::compute(*sdf, mesh, lights);
  std::vector<float> out(v.vertices * n);
  for (size_t i = 0; i < v.vertices; ++i)
    for (size_t k = 0; k < n; ++k) {
      const double root_lambda = std::sqrt(std::max(lights[k].sharpness, 1e-6));
      const double elevation = std::asin(std::clamp(glm::dot(glm::normalize(lights[k].axis), mesh.normals[i]), -1.0, 1.0));
      const double horizon = normal_cdf(root_lambda * elevation);
      const double open = normal_cdf(root_lambda * v.values[3 * (i * n + k)]);
      out[i * n + k] = float(horizon > 1e-9 ? std::clamp(open / horizon, 0.0, 1.0) : 1.0);
    }
  return out;
}

WeaveLighting weave_lighting(const SgLighting& sgs, int max_lights, const VisibilityMask* mask, const ObjectVisibility* sdf,
                             const TriangleMesh& mesh) {
  WeaveLighting out;
  out.lights = weave_lights(sgs, max_lights);
  out.visibility = weave_light_visibility(mask, sdf, mesh, out.lights);
  return out;
}

}  // namespace weft
