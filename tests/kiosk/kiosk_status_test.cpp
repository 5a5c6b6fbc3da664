// The kiosk's status file: what it holds reads back as written, a damaged or foreign file is
// refused saying what is wrong, and the writer writes every few seconds or at once on news,
// atomically, readable by every user, counting fps from the frames drawn in between.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "kiosk/kiosk_status.h"
#include "kiosk/kiosk_status_file.h"
#include "support/file_text.h"

namespace weft {
namespace {

namespace fs = std::filesystem;

KioskStatus sample() {
  KioskStatus s;
  s.state = "running";
  s.written = 1764775200;  // 2025-12-03T15:20:00Z
  s.uptime_s = 3725.5;
  s.pid = 4242;
  s.bundle = "/var/lib/weft/showroom.weft";
  s.scene = "pillow";
  s.method = "iwasaki_vertex_quadrature";
  s.display = "drm:Virtual-1";
  s.ticks = 1000;
  s.drawn = 640;
  s.fps = 12.5;
  s.last_frame_ms = 41.25;
  s.probe = "fitted";
  s.probe_updates = 17;
  s.panel = {"hid 16c0:05df", "keyboard"};
  s.knob_changes = 9;
  s.content_update_at = 1764775100;
  s.content_update = "refused: bundle x: section 'scene': checksum mismatch";
  return s;
}

using test::read_all;

TEST(KioskStatus, ReadsBackAsWritten) {
  const KioskStatus s = sample();
  const std::string text = status_json(s);
  const auto j = nlohmann::json::parse(text);  // plain JSON, for any fleet tool
  EXPECT_EQ(j.at("written"), "2025-12-03T15:20:00Z");
  EXPECT_EQ(j.at("frames").at("drawn"), 640);
  EXPECT_EQ(j.at("content_update").at("at"), "2025-12-03T15:18:20Z");
  const KioskStatus r = parse_status_json(text);
  EXPECT_EQ(r.state, s.state);
  EXPECT_EQ(r.written, s.written);
  EXPECT_EQ(r.bundle, s.bundle);
  EXPECT_EQ(r.method, s.method);
  EXPECT_EQ(r.display, s.display);
  EXPECT_EQ(r.drawn, s.drawn);
  EXPECT_EQ(r.fps, s.fps);
  EXPECT_EQ(r.panel, s.panel);
  EXPECT_EQ(r.content_update_at, s.content_update_at);
  EXPECT_EQ(r.content_update, s.content_update);
  EXPECT_EQ(status_json(r), text);
}

TEST(KioskStatus, NoContentUpdateIsNull) {
  KioskStatus s = sample();
  s.content_update_at = 0;
  s.content_update.clear();
  const auto j = nlohmann::json::parse(status_json(s));
  EXPECT_TRUE(j.at("content_update").at("at").is_null());
  EXPECT_EQ(parse_status_json(status_json(s)).content_update_at, 0);
}

TEST(KioskStatus, ADamagedOrForeignFileIsRefusedSayingWhy) {
  const std::string text = status_json(sample());
  EXPECT_THROW(parse_status_json(text.substr(0, text.size() / 2)), StatusFormatError);
  EXPECT_THROW(parse_status_json(R"({"format":"weft-knobs","version":1})"), StatusFormatError);
  auto j = nlohmann::json::parse(text);
  j["frames"].erase("drawn");
  try {
    parse_status_json(j.dump());
    ADD_FAILURE() << "a status without frames.drawn was accepted";
  } catch (const StatusFormatError& e) {
    EXPECT_NE(std::string(e.what()).find("frames.drawn"), std::string::npos) << e.what();
  }
  j = nlohmann::json::parse(text);
  j["written"] = "yesterday";
  EXPECT_THROW(parse_status_json(j.dump()), StatusFormatError);
}

TEST(KioskStatus, TextForAPersonNamesEachPart) {
  const std::string t = status_text(sample(), 1764775230);
  EXPECT_NE(t.find("state: running (pid 4242, up 1h 2m 5s)"), std::string::npos) << t;
  EXPECT_NE(t.find("written: 2025-12-03T15:20:00Z (30 s ago)"), std::string::npos) << t;
  EXPECT_NE(t.find("method: iwasaki_vertex_quadrature"), std::string::npos) << t;
  EXPECT_NE(t.find("frames: 640 drawn in 1000 ticks, 12.5 fps, last 41.2 ms"), std::string::npos) << t;
  EXPECT_NE(t.find("content update: refused: bundle x"), std::string::npos) << t;
}

TEST(StatusFile, WritesEveryFewSecondsOrAtOnceOnNews) {
  const fs::path dir = fs::temp_directory_path() / ("weft_status_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path path = dir / "status.json";
  StatusFile file(path, std::chrono::seconds(2));
  const auto t0 = StatusFile::Clock::time_point(std::chrono::hours(1));
  KioskStatus s = sample();
  s.drawn = 100;
  file.update(s, t0);
  ASSERT_TRUE(fs::exists(path));
  EXPECT_EQ(parse_status_json(read_all(path)).fps, 0.0);  // nothing to count from yet
  struct stat st {};
  ASSERT_EQ(::stat(path.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0644u);

  s.drawn = 110;
  file.update(s, t0 + std::chrono::seconds(1));  // nothing new, too soon
  EXPECT_EQ(parse_status_json(read_all(path)).drawn, 100);
  s.drawn = 140;
  file.update(s, t0 + std::chrono::seconds(2));  // due: 40 frames in 2 s
  KioskStatus r = parse_status_json(read_all(path));
  EXPECT_EQ(r.drawn, 140);
  EXPECT_DOUBLE_EQ(r.fps, 20.0);

  s.content_update_at = s.content_update_at + 60;
  s.content_update = "shown";
  file.update(s, t0 + std::chrono::milliseconds(2100));  // news: at once
  EXPECT_EQ(parse_status_json(read_all(path)).content_update, "shown");
  fs::remove_all(dir);
}

TEST(StatusFile, AnUnwritablePlaceIsLoggedNotThrown) {
  StatusFile file("/nonexistent-weft-dir/status.json");
  EXPECT_NO_THROW(file.update(sample(), StatusFile::Clock::now()));
}

TEST(StatusFile, TheDefaultIsTheServicesRuntimeDirectory) {
  ::setenv("RUNTIME_DIRECTORY", "/run/weft-test:/run/other", 1);
  EXPECT_EQ(default_status_path(), fs::path("/run/weft-test/status.json"));
  ::unsetenv("RUNTIME_DIRECTORY");
  EXPECT_EQ(default_status_path(), fs::path("/run/weft/status.json"));
}

}  // namespace
}  // namespace weft
