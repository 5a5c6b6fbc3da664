#pragma once
// `weft bundle info` and `weft bundle verify` as a person reads them.
#include <ostream>
#include <string>

#include "inspect/bundle_report.h"

namespace weft {

void write_report_text(const BundleReport& report, std::ostream& out);

// One line: "bundle FILE: ok, ..." or the kiosk's reason for refusing it.
std::string verdict_line(const BundleVerdict& verdict);

}  // namespace weft
