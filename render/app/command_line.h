#pragma once
// The command line shared by `weft` and its offline helper `weft-offline`: the subcommands a
// binary registers, the subcommands it only lists (another executable runs them), the parse,
// and the exit codes (0 ok, 1 runtime failure, 2 bad usage or bad input: docs/design.md §1).
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/commands.h"

namespace weft {

class CommandLine {
 public:
  CommandLine();
  // A subcommand this binary runs (its file's add_*_command).
  void add(CommandAction (*adder)(CLI::App&));
  // A subcommand run by another executable: shown by --help with its description, never parsed
  // here (the caller dispatches it before run()).
  void list(const char* name, const char* description);
  // Parses argv and runs the chosen subcommand; returns its exit code.
  int run(int argc, char** argv);

 private:
  CLI::App app_;
  std::vector<std::pair<CLI::App*, CommandAction>> actions_;
};

}  // namespace weft
