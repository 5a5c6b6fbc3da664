// weft-panel-sim as a program: help, the exact hex it prints, binary output, errors.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace {

struct Run {
  int status = -1;
  std::string out;
};

Run run_program(const std::string& program, const std::string& args) {
  Run r;
  FILE* p = ::popen((program + " " + args + " 2>&1").c_str(), "r");
  if (!p) return r;
  char buf[4096];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) r.out.append(buf, n);
  const int st = ::pclose(p);
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return r;
}

Run run(const std::string& args) { return run_program(WEFT_PANEL_SIM, args); }

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

// --uhid without a usable uhid device is a runtime failure (1) naming the device; a bad panel
// config is bad input (2) naming the file and field. (The uhid path itself: uhid_panel_test.)
TEST(PanelSimCli, UhidErrorsAreClear) {
  const auto script = write_script("uhid", "turn 0 +1\n");
  const auto missing = run("--uhid --uhid-path /nonexistent/uhid " + script);
  EXPECT_EQ(missing.status, 1);
  EXPECT_NE(missing.out.find("cannot open /nonexistent/uhid"), std::string::npos) << missing.out;
  const auto config = write_script("badconfig", "{\"hid\": {\"vendor_id\": \"0x12345\"}}");
  const auto bad = run("--uhid --uhid-path /nonexistent/uhid --panel-config " + config + " " + script);
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.out.find("hid.vendor_id must be a 16-bit USB id"), std::string::npos) << bad.out;
  EXPECT_EQ(run("--uhid --panel-config /nonexistent/panel.json " + script).status, 2);
  EXPECT_EQ(run("--uhid --hold-ms -5 " + script).status, 2);
  std::filesystem::remove(script);
  std::filesystem::remove(config);
}

// `weft panel --simulate`: the script through the simulated USB panel, the real HID backend,
// the mapper and the channel, printed as the fabric the renderer would draw.
TEST(WeftPanelCommand, SimulatedPanelChangesTheFabric) {
  const auto help = run_program(WEFT_BINARY, "panel --help");
  EXPECT_EQ(help.status, 0);
  EXPECT_NE(help.out.find("--simulate"), std::string::npos);
  const auto script = write_script("weftpanel", "turn 0 +5\nturn 2 +8\nturn 3 +2\n");
  const auto r = run_program(WEFT_BINARY, "panel --simulate " + script + " --sim-speed 20 --fabric linen_plain");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("weft panel: USB knob panel 1209:57ef connected"), std::string::npos) << r.out;
  std::string last_line, line;
  std::istringstream lines(r.out);
  while (std::getline(lines, line))
    if (!line.empty() && line[0] == '{') last_line = line;
  const auto j = nlohmann::json::parse(last_line);
  // Hue 195° → 210°: (0.06, 0.18, 0.30); 8 gloss steps: γ halves (12°, 24° → 6°, 12°).
  EXPECT_EQ(j["fabric"], "linen_plain");
  EXPECT_EQ(j["warp"]["A"], (std::vector<double>{0.06, 0.18, 0.3}));
  EXPECT_EQ(j["weft"]["gamma_s_deg"], 6.0);
  EXPECT_EQ(j["weft"]["gamma_v_deg"], 12.0);
  EXPECT_EQ(j["env_rotation_deg"], 10.0);
  const auto bad = run_program(WEFT_BINARY, "panel --simulate /nonexistent.knobs");
  EXPECT_EQ(bad.status, 2);
  std::filesystem::remove(script);
}

// Power cut and boot: the first run saves the knobs, the second restores them; a damaged file
// falls back to the preset and says so.
TEST(WeftPanelCommand, StateSurvivesARestartAndCorruptionFallsBack) {
  const auto dir = std::filesystem::temp_directory_path() / ("weft_panel_cli_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string state = (dir / "knobs.json").string();
  const auto turn = write_script("turn", "turn 1 -8\n");
  const auto idle = write_script("idle", "");
  auto last_json = [](const std::string& out) {
    std::string last, line;
    std::istringstream lines(out);
    while (std::getline(lines, line))
      if (!line.empty() && line[0] == '{') last = line;
    return nlohmann::json::parse(last);
  };
  const auto first = run_program(WEFT_BINARY, "panel --simulate " + turn + " --sim-speed 20 --state " + state);
  ASSERT_EQ(first.status, 0) << first.out;
  EXPECT_NE(first.out.find("no saved knob state"), std::string::npos) << first.out;
  // Brightness −8 steps halves linen's A.
  EXPECT_EQ(last_json(first.out)["warp"]["A"], (std::vector<double>{0.03, 0.12, 0.15}));
  const auto second = run_program(WEFT_BINARY, "panel --simulate " + idle + " --state " + state);
  ASSERT_EQ(second.status, 0) << second.out;
  EXPECT_NE(second.out.find("restored knob state from " + state), std::string::npos) << second.out;
  EXPECT_EQ(last_json(second.out)["weft"]["A"], (std::vector<double>{0.03, 0.12, 0.15}));

  std::ofstream(state, std::ios::trunc) << "{\"format\":\"weft-kn";  // torn
  const auto third = run_program(WEFT_BINARY, "panel --simulate " + idle + " --state " + state);
  ASSERT_EQ(third.status, 0) << third.out;
  EXPECT_NE(third.out.find("is unusable (not valid JSON"), std::string::npos) << third.out;
  EXPECT_NE(third.out.find("falling back to preset 'linen_plain'"), std::string::npos) << third.out;
  EXPECT_EQ(last_json(third.out)["weft"]["A"], (std::vector<double>{0.06, 0.24, 0.3}));

  const auto bad_source = run_program(WEFT_BINARY, "panel --source usb --duration 0.1");
  EXPECT_EQ(bad_source.status, 2);
  EXPECT_NE(bad_source.out.find("unknown source 'usb'"), std::string::npos) << bad_source.out;
  std::filesystem::remove_all(dir);
  std::filesystem::remove(turn);
  std::filesystem::remove(idle);
}
