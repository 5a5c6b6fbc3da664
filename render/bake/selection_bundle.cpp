#include "bake/selection_bundle.h"

#include <nlohmann/json.hpp>

#include "bake/iwasaki_bundle_writer.h"

namespace weft {

std::string selection_json(const SceneSelection& s, const SceneSelectionOptions& o) {
  const SceneSetting& c = s.chosen.setting;
  const SelectionKnobs& k = o.knobs;
  nlohmann::json tangent = nlohmann::json::object();
  for (const auto& [preset, t] : s.data.tables) tangent[preset] = {t.tangent_samples[0], t.tangent_samples[1]};
  nlohmann::json j = {{"target_error", o.target_error},
                      {"reached", s.reached},
                      {"error", s.chosen.error},
                      {"view_errors", s.chosen.view_errors},
                      {"frame_ms", s.chosen.ms},
                      {"bytes", s.chosen.bytes},
                      {"method", s.method},
                      {"setting", s.description},
                      {"tangent_samples", tangent},
                      {"lambda_levels", s.data.tables.empty() ? 0 : s.data.tables.begin()->second.level_count()},
                      {"svd_error", k.svd_errors[c.svd]},
                      {"views", {{"count", o.views.count}, {"spread_deg", o.views.spread_deg},
                                 {"width", o.views.width}, {"height", o.views.height}}},
                      {"settings_measured", s.tried.size()}};
  if (!s.data.visibility.empty()) {
    j["sdf_resolution"] = k.sdf_resolutions[c.sdf];
    j["pca_rms_error"] = k.pca_errors[c.pca];
  }
  return j.dump();
}

void add_selection_sections(bundle::BundleWriter& writer, const SceneSelection& s, const SceneSelectionOptions& o) {
  add_iwasaki_sections(writer, s.data);
  writer.add_json(kSelectionSection, selection_json(s, o));
}

}  // namespace weft
