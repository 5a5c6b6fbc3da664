// weft-panel-sim as a program: help, the exact hex it prints, binary output, errors.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

struct Run {
  int status = -1;
  std::string out;
};

Run run(const std::string& args) {
  Run r;
  FILE* p = ::popen((std::string(WEFT_PANEL_SIM) + " " + args + " 2>&1").c_str(), "r");
  if (!p) return r;
  char buf[4096];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) r.out.append(buf, n);
  const int st = ::pclose(p);
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return r;
}

std::string write_script(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / (name + std::to_string(::getpid()) + ".knobs");
  std::ofstream(path) << text;
  return path.string();
}

}  // namespace

TEST(PanelSimCli, Help) {
  const auto r = run("--help");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("usage: weft-panel-sim"), std::string::npos);
  EXPECT_NE(r.out.find("turn <dial 0-3>"), std::string::npos);
}

TEST(PanelSimCli, PrintsTheExactReports) {
  const auto script = write_script("cli", "turn 0 +2\nturn 3 -1 every 40\nclick 4\n");
  const auto hex = run(script);
  EXPECT_EQ(hex.status, 0) << hex.out;
  EXPECT_EQ(hex.out,
            "01 00 01 00 00 00 00 48 00\n"
            "01 01 01 00 00 00 00 98 00\n"
            "01 02 00 00 00 ff 00 c8 00\n"
            "01 03 00 00 00 00 10 d0 00\n"
            "01 04 00 00 00 00 00 20 01\n");
  const auto timed = run("--format timed " + script);
  EXPECT_NE(timed.out.find("    72.000 01 00 01"), std::string::npos) << timed.out;
  const auto binary = run("--format binary " + script);
  EXPECT_EQ(binary.out.size(), 5u * 9u);
  EXPECT_EQ(static_cast<unsigned char>(binary.out[9 * 2 + 5]), 0xFFu);
  std::filesystem::remove(script);
}

TEST(PanelSimCli, BadInputExitsTwoWithTheLine) {
  const auto script = write_script("bad", "turn 0 +1\nturn 9 +1\n");
  const auto r = run(script);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("script line 2: bad dial '9'"), std::string::npos) << r.out;
  EXPECT_EQ(run("--format csv " + script).status, 2);
  EXPECT_EQ(run("/nonexistent/script.knobs").status, 2);
  std::filesystem::remove(script);
}
