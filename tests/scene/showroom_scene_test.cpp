// The default showroom (assets/scenes/armchair.gltf, made by make_armchair.py): an armchair of
// two fabrics on a floor, its warps from TEXCOORD_0, its own camera looking at it.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "scene/scene_file.h"

using namespace weft;

TEST(ShowroomScene, ArmchairLoadsWithTwoClothMaterialsAndAFloor) {
  const std::string file = std::string(WEFT_SOURCE_ASSETS) + "/scenes/armchair.gltf";
  const Scene s = load_scene_named(file, WEFT_SOURCE_ASSETS);
  std::set<std::string> fabrics;
  size_t floors = 0;
  for (const SceneObject& o : s.objects) {
    if (o.material == Material::lambertian) {
      ++floors;
      continue;
    }
    fabrics.insert(o.fabric);
    ASSERT_FALSE(o.mesh.positions.empty()) << o.name;
    ASSERT_EQ(o.mesh.warps.size(), o.mesh.positions.size()) << o.name;
    for (size_t i = 0; i < o.mesh.positions.size(); ++i) {
      const glm::dvec3 n = o.mesh.normals[i], u = o.mesh.warps[i];
      ASSERT_NEAR(glm::length(u), 1.0, 1e-6) << o.name << " vertex " << i;
      ASSERT_NEAR(glm::dot(u, n), 0.0, 1e-6) << o.name << " vertex " << i;
      ASSERT_GE(o.mesh.positions[i].z, -1e-9) << o.name << ": below the floor";  // +Z up after import
    }
  }
  EXPECT_EQ(fabrics, (std::set<std::string>{"linen_plain", "polyester_satin_charmeuse"}));
  EXPECT_EQ(floors, 1u);
  // The glTF's camera (not one framed by the importer): above the seat, looking down at it.
  EXPECT_GT(s.camera.position.z, 0.8);
  EXPECT_LT(s.camera.target.z, s.camera.position.z);
  const glm::dvec3 view = glm::normalize(s.camera.target - s.camera.position);
  const glm::dvec3 to_seat = glm::normalize(glm::dvec3(0, 0, 0.45) - s.camera.position);
  EXPECT_GT(glm::dot(view, to_seat), std::cos(glm::radians(10.0)));
}
