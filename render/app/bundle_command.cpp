// `weft bundle info FILE` and `weft bundle verify FILE`: a bundle as the kiosk sees it, before it is
// copied to a kiosk (render/inspect/bundle_report.h). Here in `weft`, not `weft-offline`, because
// the checks are the kiosk's own and a kiosk image carries only this binary.
#include <iostream>
#include <stdexcept>

#include "app/cli_parse.h"
#include "app/commands.h"
#include "inspect/bundle_report.h"
#include "inspect/bundle_report_json.h"
#include "inspect/bundle_report_text.h"
#include "journal/journal_log.h"
#include "methods/registry.h"

namespace weft {
namespace {

struct BundleArgs {
  std::string file;
  bool json = false;
  std::string method = "auto";
};

// A bundle the kiosk would refuse is bad input: its reason on stderr, exit 2.
int refused(const std::string& message) {
  log_line("weft bundle", LogPriority::error, message);
  return 2;
}

int run_info(const BundleArgs& a) {
  BundleReport report;
  try {
    report = bundle_report(a.file);
  } catch (const bundle::BundleError& e) {
    return refused(e.what());
  }
  if (a.json)
    std::cout << to_json(report).dump(2) << "\n";
  else
    write_report_text(report, std::cout);
  return 0;
}

int run_verify(const BundleArgs& a) {
  if (a.method != "auto") as_usage("--method", [&] { return methods::method(a.method).name; });
  const BundleVerdict v = verify_bundle(a.file, a.method);
  if (a.json) std::cout << to_json(v).dump(2) << "\n";
  if (!v.ok) return refused(v.message);
  if (!a.json) std::cout << verdict_line(v) << "\n";
  return 0;
}

void add_file_options(CLI::App* sub, BundleArgs& a, const char* json_help) {
  sub->add_option("FILE", a.file, "Scene bundle (as weft bake writes it)")->required();
  sub->add_flag("--json", a.json, json_help);
}

}  // namespace

CommandAction add_bundle_command(CLI::App& app) {
  auto a = std::make_shared<BundleArgs>();
  CLI::App* sub = app.add_subcommand("bundle", "Inspect a scene bundle as the kiosk sees it: info, verify");
  sub->require_subcommand(1);
  CLI::App* info = sub->add_subcommand(
      "info", "What a bundle holds: scene, objects, fabrics, the methods the kiosk can draw it with, sections, the "
              "bake's settings and measured errors (exit 2 if the kiosk would refuse it)");
  add_file_options(info, *a, "The report as JSON (docs/content-guide.md lists the keys)");
  CLI::App* verify = sub->add_subcommand(
      "verify", "The kiosk's checks on a bundle (every checksum, every section, what the method needs): exit 0 if it "
                "would show it, 2 with the reason if not");
  add_file_options(verify, *a, "The verdict as JSON: file, ok, method, part, section, message");
  verify->add_option("--method", a->method, "Check for the method the kiosk is started with (auto or a method name)")
      ->capture_default_str();
  return [a, info] { return info->parsed() ? run_info(*a) : run_verify(*a); };
}

}  // namespace weft
