#pragma once
// The offline subcommands: `weft` lists them in --help but runs them in a helper executable,
// `weft-offline`, as git runs `git-<command>`. They bake, render the reference or measure
// (render/bake, render/reference with Embree and TBB, render/bench), and a kiosk image carries
// none of that: the binary systemd starts (`weft run`) links only the runtime. An image that
// also bakes installs the helper in <prefix>/libexec/weft.
#include <string_view>

namespace weft {

struct OfflineCommand {
  const char* name;
  const char* description;  // as its add_*_command registers it in weft-offline
};

// The offline subcommand called `name`, or nullptr.
const OfflineCommand* find_offline_command(std::string_view name);

// Runs argv (`weft <offline subcommand> ...`) in the helper, in place of this process, so its
// output and exit code are the command's. Returns only when the helper cannot be started: a
// message on stderr and exit code 1.
int exec_offline_helper(int argc, char** argv);

}  // namespace weft
