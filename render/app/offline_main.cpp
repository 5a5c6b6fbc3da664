// weft-offline: the offline subcommands of `weft` (offline_commands.h), which `weft` runs here.
// Called as `weft-offline <subcommand> ...` with weft's argv.
#include "app/command_line.h"
#include "app/commands.h"

int main(int argc, char** argv) {
  weft::CommandLine cli;
  cli.add(weft::add_eval_command);
  cli.add(weft::add_render_command);
  cli.add(weft::add_bake_tables_command);
  cli.add(weft::add_bake_command);
  cli.add(weft::add_bench_command);
  cli.add(weft::add_capture_command);
  return cli.run(argc, argv);
}
