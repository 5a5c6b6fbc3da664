#pragma once
// One spelling per option across the subcommands (the table in docs/engineer-guide.md, "Option
// names"). An option lists its name first and the spellings it replaces after it, e.g.
// "--sg-count,--fit-sgs": one option, so an old spelling sets the same variable through the same
// checks. Help shows the first long name only, so the old spellings work for a release unlisted.
#include <CLI/CLI.hpp>

namespace weft {

// Help for `app` and every subcommand added to it afterwards shows an option's short names and
// first long name only.
void show_first_names_only(CLI::App& app);

// An old spelling that cannot be a second name of the new option because it sets only part of it
// (--size W H of --width and --height): a separate option, left out of help.
CLI::Option* old_spelling(CLI::Option* option);

}  // namespace weft
