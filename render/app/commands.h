#pragma once
// Each subcommand registers its options on the `weft` app and returns the action to run once
// the command line is parsed. Actions return the exit code: 0 ok, 1 runtime failure, 2 bad
// usage or bad input (docs/design.md §1).
#include <functional>

#include <CLI/CLI.hpp>

namespace weft {

using CommandAction = std::function<int()>;

CommandAction add_eval_command(CLI::App& app);
CommandAction add_render_command(CLI::App& app);
CommandAction add_fit_command(CLI::App& app);
CommandAction add_panel_command(CLI::App& app);
CommandAction add_bake_tables_command(CLI::App& app);

CommandAction add_probe_command(CLI::App& app);
CommandAction add_bake_command(CLI::App& app);
CommandAction add_run_command(CLI::App& app);
CommandAction add_status_command(CLI::App& app);
CommandAction add_bench_command(CLI::App& app);
CommandAction add_bundle_command(CLI::App& app);
CommandAction add_capture_command(CLI::App& app);

}  // namespace weft
