#pragma once
// A scene-level selection in the bundle: the chosen setting's seed 000 sections (exactly the
// tables and visibility that were measured) and its record, the `bake/selection` JSON section
// (BUNDLE_FORMAT.md): target, whether it was reached, the measured error per view, frame time,
// bytes, the runtime method and every knob's value.
#include <string>

#include "bake/scene_selection.h"
#include "bundle/bundle_writer.h"

namespace weft {

inline constexpr const char* kSelectionSection = "bake/selection";

std::string selection_json(const SceneSelection& s, const SceneSelectionOptions& o);
void add_selection_sections(bundle::BundleWriter& writer, const SceneSelection& s, const SceneSelectionOptions& o);

}  // namespace weft
