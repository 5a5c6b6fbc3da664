#pragma once
// Test-only: a scene bundle baked by the `weft` under test with the smallest tables (seconds), in a
// temporary folder of its own, removed with the object.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace weft::test {

class SmallBundle {
public:
  // `scene` a scene name; `extra` more `weft bake` flags (e.g. --no-tables).
  explicit SmallBundle(const std::string& scene, const std::string& extra = "")
      : dir_(std::filesystem::temp_directory_path() / ("weft_small_bundle_" + std::to_string(::getpid()) + "_" + scene)) {
    std::filesystem::create_directories(dir_);
    file_ = dir_ / (scene + ".weft");
    const std::string cmd = "WEFT_ASSETS=" WEFT_SOURCE_ASSETS " " + std::string(WEFT_BINARY) + " bake --scene " + scene +
                            " --table-grid 4 --lambda-levels 2 --tangent-samples 1 1 --sdf-resolution 8 --floor-sdf-resolution 8 " +
                            extra + " --out " + file_.string() + " >" + (dir_ / "bake.log").string() + " 2>&1";
    const int status = std::system(cmd.c_str());
    exit_code_ = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  ~SmallBundle() {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  SmallBundle(const SmallBundle&) = delete;
  SmallBundle& operator=(const SmallBundle&) = delete;

  bool baked() const { return exit_code_ == 0 && std::filesystem::exists(file_); }
  const std::filesystem::path& file() const { return file_; }
  const std::filesystem::path& dir() const { return dir_; }

private:
  std::filesystem::path dir_, file_;
  int exit_code_ = -1;
};

}  // namespace weft::test
