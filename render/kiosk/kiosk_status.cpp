#include "kiosk/kiosk_status.h"

#include <cstdio>
#include <nlohmann/json.hpp>

namespace weft {
namespace {

using json = nlohmann::ordered_json;

constexpr int kVersion = 1;


std::time_t from_utc(const std::string& text, const char* field) {
  std::tm tm{};
  const char* end = strptime(text.c_str(), "%Y-%m-%dT%H:%M:%SZ", &tm);
  if (!end || *end) throw StatusFormatError(std::string("'") + field + "' is not a UTC time: '" + text + "'");
  return timegm(&tm);
}

// The value at `path` (keys, outermost first), of the type asked for.
template <class T>
T field(const json& j, std::initializer_list<const char*> path) {
  const json* at = &j;
  std::string name;
  for (const char* key : path) {
    name += (name.empty() ? "" : ".") + std::string(key);
    if (!at->is_object() || !at->contains(key)) throw StatusFormatError("'" + name + "' is missing");
    at = &(*at)[key];
  }
  try {
    return at->get<T>();
  } catch (const json::exception&) {
    throw StatusFormatError("'" + name + "' has the wrong type");
  }
}

std::string fixed(double x, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, x);
  return buf;
}

std::string duration(double s) {
  const long t = long(s);
  char buf[64];
  if (t >= 86400)
    std::snprintf(buf, sizeof buf, "%ldd %ldh %ldm", t / 86400, t % 86400 / 3600, t % 3600 / 60);
  else if (t >= 3600)
    std::snprintf(buf, sizeof buf, "%ldh %ldm %lds", t / 3600, t % 3600 / 60, t % 60);
  else
    std::snprintf(buf, sizeof buf, "%ldm %lds", t / 60, t % 60);
  return buf;
}

}  // namespace

std::string utc(std::time_t t) {
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

std::string status_json(const KioskStatus& s) {
  json j;
  j["format"] = "weft-status";
  j["version"] = kVersion;
  j["state"] = s.state;
  j["written"] = utc(s.written);
  j["uptime_s"] = s.uptime_s;
  j["pid"] = s.pid;
  j["bundle"] = {{"path", s.bundle}, {"last_good", s.last_good}, {"scene", s.scene}};
  j["method"] = s.method;
  j["display"] = s.display;
  j["frames"] = {{"ticks", s.ticks}, {"drawn", s.drawn}, {"fps", s.fps}, {"last_frame_ms", s.last_frame_ms}};
  j["probe"] = {{"state", s.probe}, {"updates", s.probe_updates}};
  j["panel"] = {{"sources", s.panel}, {"changes", s.knob_changes}};
  j["content_update"] = {{"at", s.content_update_at ? json(utc(s.content_update_at)) : json(nullptr)},
                         {"result", s.content_update}};
  return j.dump(2) + "\n";
}

KioskStatus parse_status_json(const std::string& text) {
  json j;
  try {
    j = json::parse(text);
  } catch (const json::exception& e) {
    throw StatusFormatError(std::string("not valid JSON (") + e.what() + ")");
  }
  if (!j.is_object() || !j.contains("format") || j["format"] != "weft-status") throw StatusFormatError("not a weft status file");
  if (field<int>(j, {"version"}) != kVersion) throw StatusFormatError("unsupported version " + j["version"].dump());
  KioskStatus s;
  s.state = field<std::string>(j, {"state"});
  s.written = from_utc(field<std::string>(j, {"written"}), "written");
  s.uptime_s = field<double>(j, {"uptime_s"});
  s.pid = field<long>(j, {"pid"});
  s.bundle = field<std::string>(j, {"bundle", "path"});
  s.last_good = field<bool>(j, {"bundle", "last_good"});
  s.scene = field<std::string>(j, {"bundle", "scene"});
  s.method = field<std::string>(j, {"method"});
  s.display = field<std::string>(j, {"display"});
  s.ticks = field<long>(j, {"frames", "ticks"});
  s.drawn = field<long>(j, {"frames", "drawn"});
  s.fps = field<double>(j, {"frames", "fps"});
  s.last_frame_ms = field<double>(j, {"frames", "last_frame_ms"});
  s.probe = field<std::string>(j, {"probe", "state"});
  s.probe_updates = field<std::uint64_t>(j, {"probe", "updates"});
  s.panel = field<std::vector<std::string>>(j, {"panel", "sources"});
  s.knob_changes = field<long>(j, {"panel", "changes"});
  const json at = field<json>(j, {"content_update", "at"});
  if (!at.is_null()) {
    if (!at.is_string()) throw StatusFormatError("'content_update.at' has the wrong type");
    s.content_update_at = from_utc(at.get<std::string>(), "content_update.at");
  }
  s.content_update = field<std::string>(j, {"content_update", "result"});
  return s;
}

std::string status_text(const KioskStatus& s, std::time_t now) {
  std::string panel;
  for (const auto& p : s.panel) panel += (panel.empty() ? "" : ", ") + p;
  std::string out;
  auto line = [&](const char* name, const std::string& value) { out += std::string(name) + ": " + value + "\n"; };
  line("state", s.state + " (pid " + std::to_string(s.pid) + ", up " + duration(s.uptime_s) + ")");
  line("written", utc(s.written) + " (" + std::to_string(long(now - s.written)) + " s ago)");
  line("bundle", s.bundle + (s.last_good ? " (the LAST GOOD copy: the bundle itself is unusable)" : ""));
  line("scene", s.scene);
  line("method", s.method);
  line("display", s.display);
  line("frames", std::to_string(s.drawn) + " drawn in " + std::to_string(s.ticks) + " ticks, " + fixed(s.fps, 1) +
                     " fps, last " + fixed(s.last_frame_ms, 1) + " ms");
  line("probe", s.probe + (s.probe == "off" ? "" : " (" + std::to_string(s.probe_updates) + " updates)"));
  line("panel", (panel.empty() ? std::string("none") : panel) + "; " + std::to_string(s.knob_changes) + " knob changes");
  line("content update", s.content_update_at ? s.content_update + " at " + utc(s.content_update_at) : std::string("none"));
  return out;
}

}  // namespace weft
