// weft: the one binary. Subcommands in the style of git; see `weft --help`.
#include <cstdio>
#include <iostream>

#include "app/cli_parse.h"
#include "app/commands.h"
#include "core/fabric.h"

int main(int argc, char** argv) {
  CLI::App app{"weft " WEFT_VERSION ": microcylinder cloth rendering for showroom kiosks"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("weft ") + WEFT_VERSION);
  std::vector<std::pair<CLI::App*, weft::CommandAction>> actions;
  auto add = [&](weft::CommandAction (*adder)(CLI::App&)) {
    const size_t before = app.get_subcommands({}).size();
    auto action = adder(app);
    actions.emplace_back(app.get_subcommands({})[before], std::move(action));
  };
  add(weft::add_eval_command);
  add(weft::add_render_command);
  add(weft::add_fit_command);
  add(weft::add_panel_command);
  add(weft::add_bake_tables_command);
  add(weft::add_probe_command);
  add(weft::add_bake_command);
  add(weft::add_run_command);
  add(weft::add_bench_command);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  try {
    for (auto& [sub, action] : actions)
      if (sub->parsed()) return action();
  } catch (const weft::UsageError& e) {
    std::cerr << "weft: " << e.what() << "\n";
    return 2;
  } catch (const weft::FabricError& e) {
    std::cerr << "weft: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "weft: error: " << e.what() << "\n";
    return 1;
  }
  return 2;
}
