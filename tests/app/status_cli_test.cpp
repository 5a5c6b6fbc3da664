// `weft status`: a good status file is printed for a person (and passed through with --json); a
// missing or damaged one is bad input: exit 2 and a message saying which file and what is wrong.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "kiosk/kiosk_status.h"
#include "support/file_text.h"

namespace weft {
namespace {

namespace fs = std::filesystem;

struct Ran {
  int code = -1;
  std::string out, err;
};

using test::read_all;

class StatusCli : public ::testing::Test {
protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("weft_status_cli_" + std::to_string(getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  Ran weft(const std::string& args) {
    const fs::path out = dir_ / "out.txt", err = dir_ / "err.txt";
    const int status =
        std::system((std::string(WEFT_BINARY) + " " + args + " >" + out.string() + " 2>" + err.string()).c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_all(out), read_all(err)};
  }
  fs::path write(const std::string& name, const std::string& text) {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << text;
    return p;
  }
  fs::path dir_;
};

KioskStatus running() {
  KioskStatus s;
  s.state = "running";
  s.written = 1764775200;
  s.pid = 77;
  s.bundle = "/var/lib/weft/showroom.weft";
  s.scene = "armchair";
  s.method = "iwasaki_vertex";
  s.display = "headless";
  s.ticks = 60;
  s.drawn = 12;
  s.panel = {"none"};
  return s;
}

TEST_F(StatusCli, PrintsAGoodFileForAPersonAndAsJson) {
  const std::string text = status_json(running());
  const fs::path file = write("status.json", text);
  Ran r = weft("status --file " + file.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("scene: armchair"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("method: iwasaki_vertex"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("display: headless"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("content update: none"), std::string::npos) << r.out;
  r = weft("status --json --file " + file.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, text);
}

TEST_F(StatusCli, AMissingFileIsExit2SayingSo) {
  const Ran r = weft("status --file " + (dir_ / "absent.json").string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("no status file " + (dir_ / "absent.json").string()), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "");
}

TEST_F(StatusCli, ADamagedFileIsExit2SayingWhy) {
  const std::string text = status_json(running());
  Ran r = weft("status --file " + write("cut.json", text.substr(0, text.size() / 2)).string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("unreadable: not valid JSON"), std::string::npos) << r.err;
  r = weft("status --json --file " + write("other.json", R"({"format":"weft-knobs"})").string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("not a weft status file"), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "");
}

TEST_F(StatusCli, HelpNamesTheFlags) {
  const Ran r = weft("status --help");
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("--file"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("--json"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace weft
