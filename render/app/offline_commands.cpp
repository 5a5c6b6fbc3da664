#include "app/offline_commands.h"

#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "journal/journal_log.h"

namespace weft {

namespace {

constexpr std::array<OfflineCommand, 6> kOfflineCommands{{
    {"eval", "One radiance value: a flat swatch (n=+z, warp=+x) under SGs, as JSON"},
    {"render", "Render one frame of a showroom scene to EXR (+ tone-mapped PNG)"},
    {"bake-tables", "Bake only the SG-convolved weighting tables T of one fabric and report time, size, ranks, error"},
    {"bake", "Bake a scene into a kiosk bundle (meshes, fabrics, camera, default SGs, weighting tables)"},
    {"bench", "Speed against accuracy for every GPU method: CSV, chart, report"},
    {"capture", "Fit a fabric file to photos of a swatch on the printed capture card beside a mirror ball"},
}};

constexpr const char* kHelperName = "weft-offline";

// Where the helper may be, relative to this executable's folder: the install layout
// (bin/weft, libexec/weft/weft-offline) first, then beside it (the build tree).
std::vector<std::filesystem::path> helper_candidates() {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  const std::filesystem::path dir = self.parent_path();
  return {dir / WEFT_LIBEXEC_FROM_BINDIR / kHelperName, dir / kHelperName};
}

}  // namespace

const OfflineCommand* find_offline_command(std::string_view name) {
  for (const OfflineCommand& c : kOfflineCommands)
    if (name == c.name) return &c;
  return nullptr;
}

int exec_offline_helper(int argc, char** argv) {
  const auto candidates = helper_candidates();
  std::string looked;
  for (const auto& path : candidates) {
    if (::access(path.c_str(), X_OK) == 0) {
      // argv[0] stays as typed: usage lines and messages read "weft ..." as before.
      ::execv(path.c_str(), argv);
      log_line("weft", LogPriority::error,
               std::string(argv[1]) + ": cannot run " + path.string() + ": " + std::strerror(errno));
      return 1;
    }
    looked += (looked.empty() ? "" : ", ") + path.string();
  }
  log_line("weft", LogPriority::error,
           std::string(argv[1]) + " is an offline command and its helper " + kHelperName +
               " is not installed (looked for " + looked + "); install the weft-tools package");
  return 1;
}

}  // namespace weft
