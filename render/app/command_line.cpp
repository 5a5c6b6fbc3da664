#include "app/command_line.h"

#include <string>

#include "app/cli_parse.h"
#include "app/option_spelling.h"
#include "core/fabric.h"
#include "journal/journal_log.h"

namespace weft {

CommandLine::CommandLine() : app_{"weft " WEFT_VERSION ": microcylinder cloth rendering for showroom kiosks"} {
  show_first_names_only(app_);  // before the subcommands, which take the formatter when added
  app_.require_subcommand(1);
  app_.set_version_flag("--version", std::string("weft ") + WEFT_VERSION);
}

void CommandLine::add(CommandAction (*adder)(CLI::App&)) {
  const size_t before = app_.get_subcommands({}).size();
  auto action = adder(app_);
  actions_.emplace_back(app_.get_subcommands({})[before], std::move(action));
}

void CommandLine::list(const char* name, const char* description) { app_.add_subcommand(name, description); }

int CommandLine::run(int argc, char** argv) {
  try {
    app_.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app_.exit(e);
    return code == 0 ? 0 : 2;
  }
  try {
    for (auto& [sub, action] : actions_)
      if (sub->parsed()) return action();
  } catch (const UsageError& e) {
    log_line("weft", LogPriority::error, e.what());
    return 2;
  } catch (const FabricError& e) {
    log_line("weft", LogPriority::error, e.what());
    return 2;
  } catch (const std::exception& e) {
    log_line("weft", LogPriority::error, std::string("error: ") + e.what());
    return 1;
  }
  return 2;
}

}  // namespace weft
