#pragma once
// A small reference render of a scene's own camera under SG lighting (the SGs also as the
// background), unconverged settings given: what a test measures a GPU frame against.
#include <map>
#include <string>

#include "reference/scene_render.h"

namespace weft::test {

inline ReferenceRenderResult sg_reference(const Scene& scene, const std::map<std::string, Fabric>& fabrics,
                                          const SgLighting& sgs, int width, int height, int sg_grid,
                                          int tangent_samples) {
  ReferenceLighting lighting;
  lighting.sgs = sgs;
  lighting.background = [sgs](const glm::dvec3& d) { return evaluate(sgs, d); };
  ReferenceRenderOptions ro;
  ro.width = width, ro.height = height, ro.sg_grid = sg_grid, ro.tangent_samples = tangent_samples;
  ro.check_convergence = false;
  return ReferenceRenderer(scene, fabrics, lighting, ro).render(0);
}

}  // namespace weft::test
