#pragma once
// Writes the weighting-table sections (runtime/shading_data.h: names, data, reader) into a bundle.
#include "bundle/bundle_writer.h"
#include "runtime/shading_data.h"
#include "scene/scene.h"

namespace weft {

// Adds the sections. Where `scene` is given, an object whose mesh has a pass subset
// (scene/vertex_pass_mesh.h) stores its visibility's per-vertex rows (PCA coefficients, mask bits)
// at the pass vertices only; the reader spreads them back (the bake made the others so).
void add_shading_data_sections(bundle::BundleWriter& writer, const ShadingData& data, const Scene* scene = nullptr);

}  // namespace weft
