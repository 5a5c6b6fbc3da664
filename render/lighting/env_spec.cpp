#include "lighting/env_spec.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>

namespace weft {

namespace {

const std::string kSky = "sky";

bool is_sky(const std::string& s) { return s == kSky || s.rfind(kSky + ":", 0) == 0; }

double number(const std::string& spec, const std::string& what, const std::string& text) {
  double v = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, v);
  if (text.empty() || ec != std::errc() || ptr != end || !std::isfinite(v))
    throw EnvSpecError("environment '" + spec + "': " + what + " '" + text + "' is not a number");
  return v;
}

bool numeric(const std::string& text) {
  double v = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, v);
  return !text.empty() && ec == std::errc() && ptr == end;
}

std::string short_number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

EnvSpec parse_env_spec(const std::string& spec) {
  EnvSpec e;
  std::string body = spec;
  // A suffix @<number> is a rotation; any other '@' belongs to a file name.
  if (const auto at = body.rfind('@'); at != std::string::npos && (is_sky(body) || numeric(body.substr(at + 1)))) {
    e.rotation_deg = number(spec, "rotation", body.substr(at + 1));
    body = body.substr(0, at);
  }
  if (body.empty()) throw EnvSpecError("environment '" + spec + "': no map or sky named");
  if (!is_sky(body)) {
    e.name = body;
    return e;
  }
  e.kind = EnvSpec::Kind::sky;
  std::string params = body.size() > kSky.size() ? body.substr(kSky.size() + 1) : "";
  std::istringstream in(params);
  std::string item;
  while (std::getline(in, item, ',')) {
    if (item.empty()) continue;
    const auto eq = item.find('=');
    if (eq == std::string::npos)
      throw EnvSpecError("environment '" + spec + "': '" + item + "' is not key=value");
    const std::string key = item.substr(0, eq);
    const double v = number(spec, key, item.substr(eq + 1));
    if (key == "elev") e.sky.elevation_deg = v;
    else if (key == "azim") e.sky.azimuth_deg = v;
    else if (key == "size") e.sky.size_deg = v;
    else if (key == "haze") e.sky.turbidity = v;
    else if (key == "albedo") e.sky.ground_albedo = v;
    else if (key == "width") {
      if (v != std::floor(v)) throw EnvSpecError("environment '" + spec + "': width must be a whole number");
      e.sky.width = static_cast<int>(std::clamp(v, -1.0, 1e6));
    } else
      throw EnvSpecError("environment '" + spec + "': unknown sky parameter '" + key +
                         "' (known: elev, azim, size, haze, albedo, width)");
  }
  e.sky.azimuth_deg += e.rotation_deg;
  e.rotation_deg = 0.0;
  try {
    validate(e.sky);
  } catch (const std::invalid_argument& err) {
    throw EnvSpecError("environment '" + spec + "': " + err.what());
  }
  return e;
}

bool is_env_spec(const std::string& spec) {
  const auto at = spec.rfind('@');
  return is_sky(spec) || (at != std::string::npos && numeric(spec.substr(at + 1)));
}

EnvMap load_env(const std::string& spec, const std::filesystem::path& dir, NonFinitePolicy policy,
                EnvMapRepairs* repairs) {
  const EnvSpec e = parse_env_spec(spec);
  if (e.kind == EnvSpec::Kind::sky) {
    if (repairs) *repairs = {};
    return procedural_sky(e.sky);
  }
  EnvMap map = load_env_map(env_map_file(e.name, dir), policy, repairs);
  return e.rotation_deg == 0.0 ? map : rotate_about_z(map, e.rotation_deg);
}

std::filesystem::path env_spec_file(const std::string& spec, const std::filesystem::path& dir) {
  const EnvSpec e = parse_env_spec(spec);
  return e.kind == EnvSpec::Kind::sky ? std::filesystem::path() : env_map_file(e.name, dir);
}

std::string env_spec_label(const std::string& spec) {
  if (!is_env_spec(spec)) return env_map_label(spec);
  const EnvSpec e = parse_env_spec(spec);
  if (e.kind == EnvSpec::Kind::file) return env_map_label(e.name) + "_r" + short_number(e.rotation_deg);
  const SkyParams d;
  std::string s = "sky_e" + short_number(e.sky.elevation_deg);
  if (e.sky.azimuth_deg != d.azimuth_deg) s += "_a" + short_number(e.sky.azimuth_deg);
  if (e.sky.size_deg != d.size_deg) s += "_s" + short_number(e.sky.size_deg);
  if (e.sky.turbidity != d.turbidity) s += "_h" + short_number(e.sky.turbidity);
  if (e.sky.ground_albedo != d.ground_albedo) s += "_g" + short_number(e.sky.ground_albedo);
  if (e.sky.width != d.width) s += "_w" + short_number(e.sky.width);
  return s;
}

EnvMap rotate_about_z(const EnvMap& map, double degrees) {
  // u = atan2(d.y, −d.x)/2π + 0.5 falls by degrees/360 when the azimuth grows: the texel now at
  // column x shows what was at column x + shift.
  const double shift = degrees / 360.0 * map.width;
  const double whole = std::floor(shift);
  const double t = shift - whole;
  const long long w = map.width;
  EnvMap out(map.width, map.height);
  for (int y = 0; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x) {
      const long long x0 = (((x + static_cast<long long>(whole)) % w) + w) % w;
      const long long x1 = (x0 + 1) % w;
      out.at(x, y) = (1.0f - static_cast<float>(t)) * map.at(static_cast<int>(x0), y) +
                     static_cast<float>(t) * map.at(static_cast<int>(x1), y);
    }
  return out;
}

std::vector<std::string> join_env_specs(const std::vector<std::string>& items) {
  std::vector<std::string> out;
  for (const auto& item : items) {
    const bool param = item.find('=') != std::string::npos && item.find(':') == std::string::npos;
    if (param && !out.empty() && is_sky(out.back().substr(0, out.back().rfind('@'))))
      out.back() += (out.back() == kSky ? ":" : ",") + item;
    else
      out.push_back(item);
  }
  return out;
}

}  // namespace weft
