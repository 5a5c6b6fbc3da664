// weft: the one command. Subcommands in the style of git; see `weft --help`. The kiosk's and the
// light commands run here; the offline ones (offline_commands.h) run in `weft-offline`, so the
// binary systemd starts links neither the baker nor the reference (Embree, TBB).
#include "app/command_line.h"
#include "app/commands.h"
#include "app/offline_commands.h"

int main(int argc, char** argv) {
  if (argc > 1)
    if (weft::find_offline_command(argv[1])) return weft::exec_offline_helper(argc, argv);
  auto offline = [](const char* name) { return weft::find_offline_command(name)->description; };
  weft::CommandLine cli;
  cli.list("eval", offline("eval"));
  cli.list("render", offline("render"));
  cli.add(weft::add_fit_command);
  cli.add(weft::add_panel_command);
  cli.list("bake-tables", offline("bake-tables"));
  cli.add(weft::add_probe_command);
  cli.list("bake", offline("bake"));
  cli.add(weft::add_run_command);
  cli.add(weft::add_status_command);
  cli.list("bench", offline("bench"));
  cli.list("capture", offline("capture"));
  cli.add(weft::add_bundle_command);
  return cli.run(argc, argv);
}
