// The README's folder table against the tree: every folder it names exists, and every code folder
// (render/*, input/*, firmware-host/*) is named in it, so the map a newcomer reads cannot drift.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

namespace fs = std::filesystem;

namespace {
const fs::path kRoot = fs::path(WEFT_SOURCE_ASSETS).parent_path();

// The backticked paths in the first column of the README's table rows ("| `render/gpu`, `x` | …").
std::set<std::string> named_folders() {
  std::ifstream in(kRoot / "README.md");
  std::set<std::string> out;
  const std::regex path("`([a-z][a-z0-9_-]*(/[a-z0-9_-]+)*)`");
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("| `", 0) != 0) continue;
    const std::string first = line.substr(1, line.find('|', 1) - 1);
    for (std::sregex_iterator m(first.begin(), first.end(), path), end; m != end; ++m) out.insert((*m)[1]);
  }
  return out;
}
}  // namespace

TEST(ReadmeFolders, EveryNamedFolderExistsAndEveryCodeFolderIsNamed) {
  const std::set<std::string> named = named_folders();
  ASSERT_GT(named.size(), 10u) << "no folder table found in " << kRoot / "README.md";
  for (const std::string& f : named) EXPECT_TRUE(fs::is_directory(kRoot / f)) << "the README names " << f << ", which is not a folder";
  for (const char* top : {"render", "input", "firmware-host"})
    for (const auto& e : fs::directory_iterator(kRoot / top)) {
      if (!e.is_directory()) continue;
      const std::string f = std::string(top) + "/" + e.path().filename().string();
      // A top-level folder named as a whole ("`input`") covers its rooms.
      EXPECT_TRUE(named.count(f) || (std::string(top) != "render" && named.count(top)))
          << f << " is not in the README's folder table";
    }
}
