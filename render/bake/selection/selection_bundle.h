#pragma once
// A scene-level selection in the bundle (and `weft bake --choose-rung`'s record, the same section): the chosen setting's weighting-table sections (exactly the
// tables and visibility that were measured) and its record, the `bake/selection` JSON section
// (BUNDLE_FORMAT.md): target, whether it was reached, the measured error per view, frame time,
// bytes, the runtime method and every knob's value.
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "bake/writers/scene_bundle_writer.h"
#include "bake/selection/scene_selection.h"
#include "bundle/bundle_writer.h"

namespace weft {

inline constexpr const char* kSelectionSection = "bake/selection";

std::string selection_json(const SceneSelection& s, const SceneSelectionOptions& o);
// What `weft bake --target-error` prints: the setting, the measured error per view and whether
// the target was reached (or the closest taken), bytes, frame time, the search's cost.
std::string selection_summary(const SceneSelection& s, const SceneSelectionOptions& o);
void add_selection_sections(bundle::BundleWriter& writer, const SceneSelection& s, const SceneSelectionOptions& o);

// SG counts `weft bake --target-error` searches when the SGs are fitted to the scene's map, and
// the SGs of that fit lighting the views' references: richer than any count searched (the
// shaders take up to 40).
inline const std::vector<int> kBakeSgCounts{4, 6, 8, 10, 12};
inline constexpr int kReferenceSgCount = 24;

// `weft bake --target-error`'s search: parses the scene's cloth fabrics from their texts
// (preset → JSON, as the bundle stores them), runs the selection and prints selection_summary on
// stderr. Progress lines go to stderr unless `o.log` takes them; references to `o.cache`, else
// default_reference_cache(). With `sg_map` (an environment map file) the SG count is searched
// too (kBakeSgCounts, fitted as `weft fit` does) under references lit by kReferenceSgCount SGs
// of it; without, `sgs` light the references and every setting.
SceneSelection select_for_bundle(const Scene& scene, const std::map<std::string, std::string>& fabric_texts,
                                 const SgLighting& sgs, const SceneSelectionOptions& o,
                                 const std::filesystem::path& sg_map = {});
// `weft bake --target-error`: select_for_bundle with `in`'s SGs, then `in`'s scene sections with
// the chosen SGs as the default lighting and the cloth meshes refined as chosen (`in` is left
// holding both), and the selection's sections. Returns a one-line summary.
std::string add_selected_bundle(bundle::BundleWriter& writer, SceneBundleInput& in, const SceneSelectionOptions& o,
                                const std::filesystem::path& sg_map = {});

// `weft bake --choose-rung`: choose_rung (bake/selection/rung_choice.h) between kVertexRungCandidates on `in`'s
// scene and SGs with the bundle data just baked, and its record as the `bake/selection` section.
// References to `cache`, else default_reference_cache(); progress lines to `log`, else stderr.
// Returns the summary line's part (the rung and each candidate's error), or why nothing was chosen
// (no occluded cloth).
std::string add_rung_choice(bundle::BundleWriter& writer, const SceneBundleInput& in, ShadingData baked,
                            const SelectionViewOptions& views, const std::filesystem::path& cache,
                            const std::function<void(const std::string&)>& log = {});


}  // namespace weft
