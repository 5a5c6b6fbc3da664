#pragma once
// A scene-level selection in the bundle: the chosen setting's seed 000 sections (exactly the
// tables and visibility that were measured) and its record, the `bake/selection` JSON section
// (BUNDLE_FORMAT.md): target, whether it was reached, the measured error per view, frame time,
// bytes, the runtime method and every knob's value.
#include <map>
#include <string>

#include "bake/scene_selection.h"
#include "bundle/bundle_writer.h"

namespace weft {

inline constexpr const char* kSelectionSection = "bake/selection";

std::string selection_json(const SceneSelection& s, const SceneSelectionOptions& o);
// What `weft bake --target-error` prints: the setting, the measured error per view and whether
// the target was reached (or the closest taken), bytes, frame time, the search's cost.
std::string selection_summary(const SceneSelection& s, const SceneSelectionOptions& o);
void add_selection_sections(bundle::BundleWriter& writer, const SceneSelection& s, const SceneSelectionOptions& o);

// `weft bake --target-error`'s seed 000 stage: parses the scene's cloth fabrics from their texts
// (preset → JSON, as the bundle stores them), runs the selection, adds its sections, prints
// selection_summary on stderr and returns a one-line summary. Progress lines go to stderr unless
// `o.log` takes them; references to `o.cache`, else default_reference_cache().
std::string add_selected_sections(bundle::BundleWriter& writer, const Scene& scene,
                                  const std::map<std::string, std::string>& fabric_texts, const SgLighting& sgs,
                                  const SceneSelectionOptions& o);

}  // namespace weft
