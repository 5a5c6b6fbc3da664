#pragma once
// `weft bundle info --json` and `weft bundle verify --json`: the report and the verdict as JSON for
// scripts. Every key is always present (null where it does not apply), so a script can rely on
// the shape; docs/content-guide.md lists the keys.
#include <nlohmann/json.hpp>

#include "inspect/bundle_report.h"

namespace weft {

nlohmann::json to_json(const BundleReport& report);
nlohmann::json to_json(const BundleVerdict& verdict);

}  // namespace weft
