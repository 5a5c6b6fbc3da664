#pragma once
// Writes the scene sections of a bundle (runtime/scene_bundle.h: names, reader).
#include <map>
#include <string>

#include "bundle/bundle_writer.h"
#include "runtime/scene_bundle.h"

namespace weft {

struct SceneBundleInput {
  Scene scene;                                  // meshes already finished (normals, warps)
  std::map<std::string, std::string> fabrics;   // preset name → fabric JSON text (as on disk)
  SgLighting sgs;                               // default lighting
};

// Adds the scene sections to `writer` (which may also receive other stages' tables).
void add_scene_sections(bundle::BundleWriter& writer, const SceneBundleInput& input);

// Payload bytes of one mesh's `mesh/<i>/…` sections as add_scene_sections writes them (f32
// attributes, u32 indices; without the 64-byte alignment padding).
size_t mesh_section_bytes(const TriangleMesh& mesh);

}  // namespace weft
