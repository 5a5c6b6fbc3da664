// `weft bake` + `weft run` headless: a bundle that is corrupt, truncated or
// from another format version at boot → the last good bundle, and the log says why; systemd's
// notify protocol with a listener standing in for systemd: READY=1 after the first frame,
// WATCHDOG=1 pings while the loop runs, none once the loop hangs (WEFT_FAULT_HANG_AFTER_TICKS);
// with stderr as the journal (JOURNAL_STREAM), lines carry sd-daemon priority prefixes;
// content updates while the kiosk runs: a bundle renamed into place is shown (the same picture
// as a fresh start on it), corrupt, truncated and half-copied ones are refused with a journal
// error and the picture stays, a half copy completed later is shown; the status file.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>
#include <fcntl.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>
#include "support/file_text.h"

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

using weft::test::read_all;

struct Spawned {
  pid_t pid = -1;
  fs::path log;
};

// How the child's JOURNAL_STREAM relates to its stderr (systemd.exec(5)).
enum class Journal { unset, matches_stderr, other_file };

// Starts weft with `args`, `env` added, stdout and stderr to a log file.
Spawned spawn(const std::vector<std::string>& args, const std::vector<std::string>& env, const fs::path& log,
              Journal journal = Journal::unset) {
  Spawned s;
  s.log = log;
  s.pid = fork();
  if (s.pid == 0) {
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(fd, 1);
    dup2(fd, 2);
    unsetenv("JOURNAL_STREAM");
    if (journal != Journal::unset) {
      struct stat st {};
      fstat(fd, &st);
      // other_file: a JOURNAL_STREAM inherited from a parent whose stderr was the journal.
      const auto ino = static_cast<unsigned long long>(st.st_ino) + (journal == Journal::other_file ? 1 : 0);
      setenv("JOURNAL_STREAM", (std::to_string(st.st_dev) + ":" + std::to_string(ino)).c_str(), 1);
    }
    for (const auto& e : env) putenv(strdup(e.c_str()));
    std::vector<char*> argv{const_cast<char*>(WEFT_BINARY)};
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(WEFT_BINARY, argv.data());
    _exit(127);
  }
  return s;
}

int wait_exit(const Spawned& s) {
  int status = 0;
  waitpid(s.pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace

class KioskRun : public ::testing::Test {
protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("weft_kiosk_" + std::to_string(getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    // Scene sections only: these tests are about the bundle and the loop (sgpoint draws it);
    // shading_data_test covers a bundle with the weighting tables.
    const Spawned b = spawn({"bake", "--scene", "pillow", "--fabric", "linen_plain", "--no-tables", "--out", (dir_ / "good.weft").string()},
                            {}, dir_ / "bake.log");
    ASSERT_EQ(wait_exit(b), 0) << read_all(dir_ / "bake.log");
    // Another scene and fabric, for content updates.
    const Spawned o = spawn({"bake", "--scene", "swatch", "--fabric", "silk_shot", "--no-tables", "--out", (dir_ / "other.weft").string()},
                            {}, dir_ / "bake_other.log");
    ASSERT_EQ(wait_exit(o), 0) << read_all(dir_ / "bake_other.log");
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }

  // weft run headless, 2 ticks, still camera, no panel; returns exit code, log in `log`.
  int run(const fs::path& bundle, const fs::path& state, const fs::path& png, std::string& log,
          const std::string& panel = "none", const std::string& frames = "2", const std::string& probe = "none",
          Journal journal = Journal::unset) {
    std::vector<std::string> args{"run", "--bundle", bundle.string(), "--state-dir", state.string(), "--display",
                                  "headless", "--frames", frames, "--turntable", "0", "--panel", panel, "--width", "96",
                                  "--height", "72", "--screenshot", png.string(), "--probe", probe};
    const Spawned s = spawn(args, {}, dir_ / "run.log", journal);
    const int rc = wait_exit(s);
    log = read_all(dir_ / "run.log");
    return rc;
  }
  // The log's lines that contain `needle`.
  static std::vector<std::string> lines_with(const std::string& log, const std::string& needle) {
    std::vector<std::string> found;
    std::istringstream in(log);
    for (std::string line; std::getline(in, line);)
      if (line.find(needle) != std::string::npos) found.push_back(line);
    return found;
  }
  static fs::path dir_;
};
fs::path KioskRun::dir_;

TEST_F(KioskRun, BakeWritesTheDocumentedSections) {
  const std::string log = read_all(dir_ / "bake.log");
  EXPECT_NE(log.find("baked"), std::string::npos) << log;
  const std::string bytes = read_all(dir_ / "good.weft");
  for (const char* name : {"scene", "lighting/sgs", "fabrics", "mesh/0/positions", "mesh/0/warps", "mesh/0/indices"})
    EXPECT_NE(bytes.find(std::string(name) + std::string(1, '\0')), std::string::npos) << name;
}

TEST_F(KioskRun, BadBundlesAtBootFallBackToTheLastGoodOne) {
  const fs::path state = dir_ / "state";
  std::string log;
  ASSERT_EQ(run(dir_ / "good.weft", state, dir_ / "good.png", log), 0) << log;
  EXPECT_NE(log.find("first frame"), std::string::npos) << log;
  EXPECT_EQ(log.find("LAST GOOD"), std::string::npos) << log;
  ASSERT_TRUE(fs::exists(state / "last-good.weftbundle"));
  const std::string good_png = read_all(dir_ / "good.png");
  ASSERT_GT(good_png.size(), 100u);

  const std::string good = read_all(dir_ / "good.weft");
  struct Fault {
    const char* name;
    std::string bytes;
    const char* why;  // what the log must say
  };
  std::string flipped = good;
  flipped[good.size() - 100] ^= 0x10;  // in the last section's payload
  std::string wrong_version = good;
  wrong_version[8] = 2;
  const std::vector<Fault> faults{{"corrupt", flipped, "checksum mismatch"},
                                  {"truncated", good.substr(0, good.size() / 2), "truncated"},
                                  {"wrong-version", wrong_version, "format version 2"}};
  for (const auto& f : faults) {
    const fs::path bad = dir_ / (std::string(f.name) + ".weft");
    std::ofstream(bad, std::ios::binary) << f.bytes;
    const fs::path png = dir_ / (std::string(f.name) + ".png");
    ASSERT_EQ(run(bad, state, png, log), 0) << f.name << "\n" << log;
    EXPECT_NE(log.find("LAST GOOD"), std::string::npos) << f.name << "\n" << log;
    EXPECT_NE(log.find(f.why), std::string::npos) << f.name << "\n" << log;
    EXPECT_NE(log.find("first frame"), std::string::npos) << f.name << "\n" << log;
    // The same picture as from the good bundle.
    EXPECT_EQ(read_all(png), good_png) << f.name;
  }
  // No last good copy and a bad bundle: a clear failure, no crash.
  ASSERT_EQ(run(dir_ / "corrupt.weft", dir_ / "empty_state", dir_ / "none.png", log), 1) << log;
  EXPECT_NE(log.find("no usable bundle"), std::string::npos) << log;
}

// sd-daemon(3): "<4>" warning, "<6>" info, "<3>" error, so `journalctl -p warning` lists the
// fallback; on a plain file, even with an unrelated JOURNAL_STREAM inherited, the text is as it was.
TEST_F(KioskRun, UnderTheJournalEachLineCarriesItsPriority) {
  const fs::path state = dir_ / "journal_state";
  std::string log;
  ASSERT_EQ(run(dir_ / "good.weft", state, dir_ / "journal_good.png", log), 0) << log;
  std::string corrupt = read_all(dir_ / "good.weft");
  corrupt[corrupt.size() - 100] ^= 0x10;
  const fs::path bad = dir_ / "journal_corrupt.weft";
  std::ofstream(bad, std::ios::binary) << corrupt;

  ASSERT_EQ(run(bad, state, dir_ / "journal.png", log, "none", "2", "none", Journal::matches_stderr), 0) << log;
  const auto fallback = lines_with(log, "falling back to the last good bundle");
  ASSERT_EQ(fallback.size(), 1u) << log;
  EXPECT_EQ(fallback[0].rfind("<4>weft run: ", 0), 0u) << fallback[0];
  EXPECT_NE(fallback[0].find("checksum mismatch"), std::string::npos) << fallback[0];
  const auto first = lines_with(log, "first frame after");
  ASSERT_EQ(first.size(), 1u) << log;
  EXPECT_EQ(first[0].rfind("<6>weft run: ", 0), 0u) << first[0];
  for (const auto& line : lines_with(log, "weft run: "))
    EXPECT_TRUE(line.rfind("<3>", 0) == 0 || line.rfind("<4>", 0) == 0 || line.rfind("<6>", 0) == 0) << line;

  ASSERT_EQ(run(bad, dir_ / "journal_empty", dir_ / "none.png", log, "none", "2", "none", Journal::matches_stderr), 1)
      << log;
  const auto none = lines_with(log, "no usable bundle");
  ASSERT_FALSE(none.empty()) << log;
  for (const auto& line : none) EXPECT_EQ(line.rfind("<3>weft", 0), 0u) << line;

  ASSERT_EQ(run(bad, state, dir_ / "journal.png", log, "none", "2", "none", Journal::other_file), 0) << log;
  const auto plain = lines_with(log, "falling back to the last good bundle");
  ASSERT_EQ(plain.size(), 1u) << log;
  EXPECT_EQ(plain[0].rfind("weft run: ", 0), 0u) << plain[0];
  EXPECT_EQ(log.find("<4>"), std::string::npos) << log;
  EXPECT_EQ(log.find("<6>"), std::string::npos) << log;
}

TEST_F(KioskRun, KnobStateIsRestoredFromTheStateDir) {
  const fs::path state = dir_ / "knob_state";
  fs::create_directories(state);
  std::string log;
  ASSERT_EQ(run(dir_ / "good.weft", state, dir_ / "plain.png", log), 0) << log;
  // A saved knob state with the hue turned: the picture changes, and the log says restored.
  const std::string plain = read_all(dir_ / "plain.png");
  ASSERT_TRUE(fs::exists(state / "knobs.json") || log.find("knob") != std::string::npos) << log;
  std::ofstream(dir_ / "turn.knobs") << "turn 0 12 every 5\nwait 50\n";
  ASSERT_EQ(run(dir_ / "good.weft", state, dir_ / "turned.png", log,
                "sim:" + (dir_ / "turn.knobs").string(), "60"),
            0)
      << log;
  EXPECT_NE(read_all(dir_ / "turned.png"), plain) << log;
  ASSERT_TRUE(fs::exists(state / "knobs.json")) << log;
  // Next boot without the panel: the turned state comes back from the state dir.
  ASSERT_EQ(run(dir_ / "good.weft", state, dir_ / "restored.png", log), 0) << log;
  EXPECT_EQ(read_all(dir_ / "restored.png"), read_all(dir_ / "turned.png")) << log;
  // With --idle-return 1 nobody touches the knobs: after a second the look eases home over 3 s,
  // and the picture and the state file are the untouched ones again.
  const Spawned s = spawn({"run", "--bundle", (dir_ / "good.weft").string(), "--state-dir", state.string(), "--display",
                           "headless", "--frames", "420", "--turntable", "0", "--panel", "none", "--width", "96", "--height",
                           "72", "--screenshot", (dir_ / "home.png").string(), "--idle-return", "1"},
                          {}, dir_ / "idle.log");
  ASSERT_EQ(wait_exit(s), 0) << read_all(dir_ / "idle.log");
  log = read_all(dir_ / "idle.log");
  EXPECT_EQ(lines_with(log, "easing back to preset").size(), 1u) << log;
  EXPECT_TRUE(read_all(dir_ / "home.png") == plain) << "the picture after the way home is not the untouched one: " << log;
  ASSERT_EQ(run(dir_ / "good.weft", state, dir_ / "after_home.png", log), 0) << log;
  EXPECT_TRUE(read_all(dir_ / "after_home.png") == plain) << "the state file keeps the look at home: " << log;
}

TEST_F(KioskRun, TheColourwayButtonDressesTheClothInTheNextColourwayAndTheStateDirRemembersIt) {
  // The pillow with two colourways; the panel config gives push dial 3 to the colourway.
  const fs::path state = dir_ / "colourway_state";
  fs::create_directories(state);
  std::ifstream in(fs::path(WEFT_SOURCE_ASSETS) / "scenes" / "pillow.json");
  nlohmann::json scene = nlohmann::json::parse(in);
  scene["colourways"] = nlohmann::json::parse(R"([
      {"name": "Ocean", "objects": {"pillow": {"fabric": "linen_plain", "colour": [0.1, 0.3, 0.6]}}},
      {"name": "Rust", "objects": {"pillow": {"fabric": "linen_plain", "colour": [0.7, 0.25, 0.05]}}}])");
  std::ofstream(dir_ / "pillow_colourways.json") << scene.dump();
  const Spawned b = spawn({"bake", "--scene", (dir_ / "pillow_colourways.json").string(), "--no-tables", "--out",
                           (dir_ / "colourways.weft").string()},
                          {}, dir_ / "bake_colourways.log");
  ASSERT_EQ(wait_exit(b), 0) << read_all(dir_ / "bake_colourways.log");
  std::ofstream(dir_ / "colourway_panel.json") << R"({"colourway_button": 3})";
  std::ofstream(dir_ / "colourway.knobs") << "wait 100\nclick 3\nwait 300\n";
  const auto run_with = [&](const std::string& panel, const std::string& frames, const fs::path& png) {
    const Spawned s = spawn({"run", "--bundle", (dir_ / "colourways.weft").string(), "--state-dir", state.string(),
                             "--display", "headless", "--frames", frames, "--turntable", "0", "--panel", panel,
                             "--panel-config", (dir_ / "colourway_panel.json").string(), "--width", "96", "--height",
                             "72", "--screenshot", png.string(), "--probe", "none"},
                            {}, dir_ / "run_colourway.log");
    EXPECT_EQ(wait_exit(s), 0) << read_all(dir_ / "run_colourway.log");
    return read_all(dir_ / "run_colourway.log");
  };
  std::string log = run_with("none", "2", dir_ / "ocean.png");
  EXPECT_NE(log.find("wearing colourway 'Ocean'"), std::string::npos) << log;
  log = run_with("sim:" + (dir_ / "colourway.knobs").string(), "60", dir_ / "rust.png");
  EXPECT_NE(log.find("wearing colourway 'Rust'"), std::string::npos) << log;
  EXPECT_NE(read_all(dir_ / "rust.png"), read_all(dir_ / "ocean.png"));
  ASSERT_TRUE(fs::exists(state / "knobs.json")) << log;
  EXPECT_EQ(nlohmann::json::parse(read_all(state / "knobs.json")).value("colourway", ""), "Rust");
  // Next boot without the panel: Rust again, the same picture.
  log = run_with("none", "2", dir_ / "restored_rust.png");
  EXPECT_NE(log.find("colourway 'Rust'"), std::string::npos) << log;
  EXPECT_EQ(read_all(dir_ / "restored_rust.png"), read_all(dir_ / "rust.png")) << log;
}

TEST_F(KioskRun, ExposureBiasIsInStopsAndTheMultiplierIsTheSameBias) {
  // --exposure X is the bias log2(X): 2 and +1 EV write the same screenshot; +1 EV is not the
  // metered default; out-of-range values are bad usage (exit 2) naming the flag.
  const auto shot = [&](const std::vector<std::string>& extra, const std::string& name, std::string& log) {
    std::vector<std::string> args{"run", "--bundle", (dir_ / "good.weft").string(), "--state-dir", (dir_ / ("st_" + name)).string(),
                                  "--display", "headless", "--frames", "2", "--turntable", "0", "--panel", "none",
                                  "--width", "96", "--height", "72", "--screenshot", (dir_ / (name + ".png")).string()};
    args.insert(args.end(), extra.begin(), extra.end());
    const int rc = wait_exit(spawn(args, {}, dir_ / (name + ".log")));
    log = read_all(dir_ / (name + ".log"));
    return rc;
  };
  std::string log;
  ASSERT_EQ(shot({}, "metered", log), 0) << log;
  ASSERT_EQ(shot({"--exposure-bias", "1"}, "bias", log), 0) << log;
  ASSERT_EQ(shot({"--exposure", "2"}, "multiplier", log), 0) << log;
  EXPECT_EQ(read_all(dir_ / "bias.png"), read_all(dir_ / "multiplier.png"));
  EXPECT_NE(read_all(dir_ / "bias.png"), read_all(dir_ / "metered.png"));
  EXPECT_EQ(shot({"--exposure", "0"}, "zero", log), 2) << log;
  EXPECT_NE(log.find("--exposure"), std::string::npos) << log;
  EXPECT_EQ(shot({"--exposure-bias", "40"}, "far", log), 2) << log;
  EXPECT_NE(log.find("--exposure-bias"), std::string::npos) << log;
}

TEST_F(KioskRun, TheLightProbeRelightsTheRoomAndAnAbsentCameraKeepsTheStoredLight) {
  // The bundle is lit by SGs fitted to the studio map. A mocked probe camera in the interior map
  // hands the frame loop new SGs: the picture changes. A real camera that is not there (this
  // machine has none) leaves the stored lighting: the picture is the plain one, and the log says why.
  const fs::path state = dir_ / "probe_state";
  fs::create_directories(state);
  std::string log;
  ASSERT_EQ(run(dir_ / "good.weft", state, dir_ / "probe_plain.png", log, "none", "30"), 0) << log;
  const std::string plain = read_all(dir_ / "probe_plain.png");
  const std::string interior = std::string(WEFT_SOURCE_ASSETS) + "/envmaps/interior.exr";
  ASSERT_EQ(run(dir_ / "good.weft", state, dir_ / "probe_mock.png", log, "none", "150", "mock:" + interior), 0) << log;
  EXPECT_NE(read_all(dir_ / "probe_mock.png"), plain) << log;
  ASSERT_EQ(run(dir_ / "good.weft", state, dir_ / "probe_absent.png", log, "none", "30", "camera:no-such-camera"), 0)
      << log;
  EXPECT_EQ(read_all(dir_ / "probe_absent.png"), plain) << log;
  EXPECT_NE(log.find("light probe: "), std::string::npos) << log;
  // A probe that cannot be set up at all is a usage error, before anything is shown.
  EXPECT_EQ(run(dir_ / "good.weft", state, dir_ / "probe_bad.png", log, "none", "2", "mock:/no/such/map.exr"), 2) << log;
}

// A unix datagram socket standing in for systemd's NOTIFY_SOCKET.
struct NotifyListener {
  int fd = -1;
  fs::path path;
  explicit NotifyListener(const fs::path& p) : path(p) {
    fd = socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC, 0);
    sockaddr_un a{};
    a.sun_family = AF_UNIX;
    std::strncpy(a.sun_path, p.c_str(), sizeof a.sun_path - 1);
    fs::remove(p);
    bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a);
  }
  ~NotifyListener() {
    close(fd);
    fs::remove(path);
  }
  // Next message within `timeout`, or "" .
  std::string next(std::chrono::milliseconds timeout) {
    pollfd p{fd, POLLIN, 0};
    if (poll(&p, 1, int(timeout.count())) <= 0) return "";
    char buf[4096];
    const ssize_t n = recv(fd, buf, sizeof buf, 0);
    return n > 0 ? std::string(buf, size_t(n)) : "";
  }
};

TEST_F(KioskRun, NotifiesReadyAfterTheFirstFrameAndPingsTheWatchdogUntilTheLoopHangs) {
  NotifyListener sd(dir_ / "notify.sock");
  ASSERT_GE(sd.fd, 0);
  constexpr int kWatchdogMs = 600;
  // The loop hangs after 90 ticks (~1.5 s at 60 Hz); runs otherwise forever.
  const Spawned s = spawn({"run", "--bundle", (dir_ / "good.weft").string(), "--state-dir", (dir_ / "wd_state").string(),
                           "--display", "headless", "--frames", "0", "--turntable", "0", "--panel", "none", "--width",
                           "96", "--height", "72"},
                          {"NOTIFY_SOCKET=" + sd.path.string(), "WATCHDOG_USEC=" + std::to_string(kWatchdogMs * 1000),
                           "WEFT_FAULT_HANG_AFTER_TICKS=90"},
                          dir_ / "wd.log");
  // READY=1 comes first (before any ping), after the log's "first frame" line.
  std::string m;
  const auto start = Clock::now();
  while ((m = sd.next(std::chrono::seconds(60))).find("READY=1") == std::string::npos) {
    ASSERT_FALSE(m.empty()) << "no READY=1\n" << read_all(s.log);
    ASSERT_EQ(m.find("WATCHDOG=1"), std::string::npos) << "ping before READY";
  }
  EXPECT_NE(read_all(s.log).find("first frame"), std::string::npos) << read_all(s.log);
  EXPECT_NE(m.find("STATUS=showing 'pillow'"), std::string::npos) << m;
  (void)start;
  // Pings while the loop runs: each within the watchdog interval of the last (the service
  // would be killed otherwise). Then the hang: no ping for 3 intervals.
  int pings = 0;
  auto last = Clock::now();
  bool stopped = false;
  while (!stopped) {
    m = sd.next(std::chrono::milliseconds(3 * kWatchdogMs));
    if (m.empty()) {
      stopped = true;
      break;
    }
    if (m.find("WATCHDOG=1") == std::string::npos) continue;
    const auto now = Clock::now();
    EXPECT_LT(now - last, std::chrono::milliseconds(kWatchdogMs)) << "ping " << pings;
    last = now;
    ++pings;
    ASSERT_LT(pings, 1000) << "the loop never hung";
  }
  // About 1.5 s of loop at one ping per 300 ms (~5).
  EXPECT_GE(pings, 3);
  EXPECT_LE(pings, 20);  // generous: a loaded CI machine stretches the 90 ticks
  // The process is still there, hung: systemd would now kill it (SIGABRT); we use SIGKILL.
  EXPECT_EQ(waitpid(s.pid, nullptr, WNOHANG), 0) << read_all(s.log);
  EXPECT_NE(read_all(s.log).find("FAULT INJECTION"), std::string::npos);
  kill(s.pid, SIGKILL);
  wait_exit(s);
}

TEST_F(KioskRun, WritesAStatusFileAFleetCanRead) {
  // --status-file: the last status (written at shutdown) names the bundle, scene, method and
  // display, and counts every tick; without the flag the service's RuntimeDirectory holds it.
  const fs::path status = dir_ / "status" / "status.json";
  fs::create_directories(status.parent_path());
  const auto run_with = [&](const std::vector<std::string>& extra, const std::vector<std::string>& env) {
    std::vector<std::string> args{"run", "--bundle", (dir_ / "good.weft").string(), "--state-dir", (dir_ / "st_status").string(),
                                  "--display", "headless", "--frames", "30", "--turntable", "0", "--panel", "none",
                                  "--size", "96", "72"};
    args.insert(args.end(), extra.begin(), extra.end());
    return wait_exit(spawn(args, env, dir_ / "status.log"));
  };
  ASSERT_EQ(run_with({"--status-file", status.string()}, {}), 0) << read_all(dir_ / "status.log");
  const auto j = nlohmann::json::parse(read_all(status));
  EXPECT_EQ(j.at("format"), "weft-status");
  EXPECT_EQ(j.at("state"), "stopping");
  EXPECT_EQ(j.at("bundle").at("path"), (dir_ / "good.weft").string());
  EXPECT_EQ(j.at("bundle").at("last_good"), false);
  EXPECT_EQ(j.at("bundle").at("scene"), "pillow");
  EXPECT_EQ(j.at("method"), "sgpoint");
  EXPECT_EQ(j.at("display"), "headless");
  EXPECT_EQ(j.at("frames").at("ticks"), 30);
  EXPECT_GE(j.at("frames").at("drawn").get<long>(), 1);
  EXPECT_LE(j.at("frames").at("drawn").get<long>(), 31);
  EXPECT_EQ(j.at("probe").at("state"), "off");
  EXPECT_TRUE(j.at("content_update").at("at").is_null());
  struct stat st {};
  ASSERT_EQ(stat(status.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0644u);  // operators read it, whatever the service's umask

  const fs::path runtime = dir_ / "runtime";
  fs::create_directories(runtime);
  ASSERT_EQ(run_with({}, {"RUNTIME_DIRECTORY=" + runtime.string()}), 0) << read_all(dir_ / "status.log");
  EXPECT_EQ(nlohmann::json::parse(read_all(runtime / "status.json")).at("frames").at("ticks"), 30);
}

TEST_F(KioskRun, SigtermStopsCleanly) {
  NotifyListener sd(dir_ / "notify2.sock");
  const Spawned s = spawn({"run", "--bundle", (dir_ / "good.weft").string(), "--state-dir", (dir_ / "term_state").string(),
                           "--display", "headless", "--frames", "0", "--panel", "none", "--width", "96", "--height", "72"},
                          {"NOTIFY_SOCKET=" + sd.path.string()}, dir_ / "term.log");
  std::string m;
  while ((m = sd.next(std::chrono::seconds(60))).find("READY=1") == std::string::npos)
    ASSERT_FALSE(m.empty()) << read_all(s.log);
  kill(s.pid, SIGTERM);
  EXPECT_EQ(wait_exit(s), 0) << read_all(s.log);
  EXPECT_NE(read_all(s.log).find("stopping after"), std::string::npos) << read_all(s.log);
}

// Content updates: `weft run` on a bundle that is replaced while it runs, with stderr as the journal.
class KioskContentUpdate : public KioskRun {
protected:
  static constexpr auto kDeadline = std::chrono::seconds(120);  // a loaded machine; no timing asserted

  // Starts the kiosk on a copy of good.weft in its own folder; returns once the first frame is up.
  void start(const std::string& name) {
    folder_ = dir_ / name;
    fs::remove_all(folder_);
    fs::create_directories(folder_);
    bundle_ = folder_ / "showroom.weft";
    fs::copy_file(dir_ / "good.weft", bundle_);
    kiosk_ = spawn({"run", "--bundle", bundle_.string(), "--state-dir", (folder_ / "state").string(), "--display",
                    "headless", "--frames", "0", "--turntable", "0", "--panel", "none", "--width", "96", "--height", "72",
                    "--stats-every", "0", "--screenshot", (folder_ / "last.png").string()},
                   {}, folder_ / "run.log", Journal::matches_stderr);
    wait_for("first frame after", 1);
  }
  // Waits until the log has `count` lines containing `needle`; returns them.
  std::vector<std::string> wait_for(const std::string& needle, size_t count) {
    const auto until = Clock::now() + kDeadline;
    for (;;) {
      const std::string log = read_all(kiosk_.log);
      auto found = lines_with(log, needle);
      if (found.size() >= count) return found;
      if (waitpid(kiosk_.pid, nullptr, WNOHANG) != 0) {
        ADD_FAILURE() << "the kiosk exited while waiting for '" << needle << "'\n" << log;
        return found;
      }
      if (Clock::now() > until) {
        ADD_FAILURE() << "no " << count << " x '" << needle << "' within the deadline\n" << log;
        return found;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
  }
  // SIGTERM; the screenshot of the last frame shown.
  std::string stop() {
    kill(kiosk_.pid, SIGTERM);
    EXPECT_EQ(wait_exit(kiosk_), 0) << read_all(kiosk_.log);
    return read_all(folder_ / "last.png");
  }
  // Written beside the bundle, then renamed over it: what rsync, systemd-sysupdate or a pull do.
  void replace_atomically(const std::string& bytes) {
    const fs::path tmp = folder_ / ".showroom.weft.partial";
    std::ofstream(tmp, std::ios::binary) << bytes;
    fs::rename(tmp, bundle_);
  }
  // A fresh kiosk's picture of `bundle` (new state dir: its own preset, knobs untouched).
  std::string fresh_render(const fs::path& bundle, const std::string& name) {
    std::string log;
    EXPECT_EQ(run(bundle, dir_ / (name + "_state"), dir_ / (name + ".png"), log), 0) << log;
    return read_all(dir_ / (name + ".png"));
  }

  fs::path folder_, bundle_;
  Spawned kiosk_;
};

TEST_F(KioskContentUpdate, ABundleRenamedIntoPlaceIsShownWithoutARestart) {
  const std::string pillow = fresh_render(dir_ / "good.weft", "update_pillow");
  const std::string swatch = fresh_render(dir_ / "other.weft", "update_swatch");
  ASSERT_NE(pillow, swatch);
  start("atomic");
  replace_atomically(read_all(dir_ / "other.weft"));
  const auto shown = wait_for("shown", 1);
  ASSERT_EQ(shown.size(), 1u);
  EXPECT_EQ(shown[0].rfind("<6>weft run: bundle " + bundle_.string() + " shown ", 0), 0u) << shown[0];
  EXPECT_NE(shown[0].find("ms after it changed: scene 'swatch'"), std::string::npos) << shown[0];
  // The swatch wears silk_shot, the pillow linen_plain: the knobs start over on the new preset.
  const auto reset = lines_with(read_all(kiosk_.log), "knob state reset to preset 'silk_shot'");
  EXPECT_EQ(reset.size(), 1u) << read_all(kiosk_.log);
  EXPECT_EQ(stop(), swatch) << read_all(kiosk_.log);
  // The new content became the last good copy.
  EXPECT_EQ(read_all(folder_ / "state" / "last-good.weftbundle"), read_all(dir_ / "other.weft"));
  EXPECT_EQ(read_all(kiosk_.log).find("<3>"), std::string::npos) << read_all(kiosk_.log);
}

TEST_F(KioskContentUpdate, CorruptTruncatedAndHalfCopiedBundlesAreRefusedAndTheSceneStays) {
  const std::string pillow = fresh_render(dir_ / "good.weft", "refused_pillow");
  const std::string other = read_all(dir_ / "other.weft");
  start("refused");
  std::string flipped = other;
  flipped[other.size() - 100] ^= 0x10;  // in the last section's payload
  replace_atomically(flipped);
  auto refused = wait_for("content update refused", 1);
  replace_atomically(other.substr(0, other.size() / 2));
  refused = wait_for("content update refused", 2);
  // A copy written in place (the file truncated, then written) and cut off half way.
  {
    std::ofstream in_place(bundle_, std::ios::binary | std::ios::trunc);
    in_place << other.substr(0, other.size() / 2);
  }
  refused = wait_for("content update refused", 3);
  ASSERT_EQ(refused.size(), 3u);
  const char* why[] = {"checksum mismatch", "truncated", "truncated"};
  for (size_t i = 0; i < refused.size(); ++i) {
    EXPECT_EQ(refused[i].rfind("<3>weft run: content update refused: bundle " + bundle_.string() + ": ", 0), 0u) << refused[i];
    EXPECT_NE(refused[i].find(why[i]), std::string::npos) << refused[i];
    EXPECT_NE(refused[i].find("still showing 'pillow'"), std::string::npos) << refused[i];
  }
  EXPECT_EQ(lines_with(read_all(kiosk_.log), " shown ").size(), 0u) << read_all(kiosk_.log);
  EXPECT_EQ(stop(), pillow) << read_all(kiosk_.log);
  // None of them replaced the last good copy.
  EXPECT_EQ(read_all(folder_ / "state" / "last-good.weftbundle"), read_all(dir_ / "good.weft"));
}

TEST_F(KioskContentUpdate, AHalfCopyCompletedLaterIsShown) {
  const std::string swatch = fresh_render(dir_ / "other.weft", "resumed_swatch");
  const std::string other = read_all(dir_ / "other.weft");
  start("resumed");
  {
    std::ofstream in_place(bundle_, std::ios::binary | std::ios::trunc);
    in_place << other.substr(0, other.size() / 3);
  }
  wait_for("content update refused", 1);
  {
    std::ofstream resumed(bundle_, std::ios::binary | std::ios::app);  // the copy resumed where it stopped
    resumed << other.substr(other.size() / 3);
  }
  wait_for("scene 'swatch'", 1);
  EXPECT_EQ(stop(), swatch) << read_all(kiosk_.log);
}
