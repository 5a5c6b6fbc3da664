// `weft status`: the running kiosk's status file (render/kiosk/kiosk_status.h), for a person or,
// with --json, as written. This file parses the flags, reads the file and prints it.
#include <ctime>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "app/cli_parse.h"
#include "app/commands.h"
#include "kiosk/kiosk_status.h"
#include "kiosk/kiosk_status_file.h"

namespace weft {
namespace {

struct StatusArgs {
  std::string file = default_status_path().string();
  bool json = false;
};

int print_status(const StatusArgs& a) {
  if (!std::filesystem::exists(a.file))
    throw UsageError("no status file " + a.file + " (is weft.service running? `weft run` writes it under its " +
                     "RuntimeDirectory, or where --status-file says)");
  const std::string text = read_argument_file(a.file, "--file");
  KioskStatus s;
  try {
    s = parse_status_json(text);
  } catch (const StatusFormatError& e) {
    throw UsageError("status file " + a.file + " is unreadable: " + e.what());
  }
  if (a.json)
    std::cout << text;
  else
    std::cout << status_text(s, std::time(nullptr));
  return 0;
}

}  // namespace

CommandAction add_status_command(CLI::App& app) {
  auto a = std::make_shared<StatusArgs>();
  CLI::App* sub = app.add_subcommand(
      "status", "The running kiosk's health: scene and method shown, fps, probe, panel, display, last content update");
  sub->add_option("--file", a->file, "Status file written by `weft run` (--status-file)")->capture_default_str();
  sub->add_flag("--json", a->json, "Print the file as written (JSON), once it is known to parse");
  return [a] { return print_status(*a); };
}

}  // namespace weft
