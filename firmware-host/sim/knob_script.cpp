#include "sim/knob_script.h"

#include <cmath>
#include <sstream>

#include "firmware/hid_report.h"

namespace weft::sim {
namespace {

[[noreturn]] void fail(int line, const std::string& what) {
  throw ScriptError("script line " + std::to_string(line) + ": " + what);
}

double parse_ms(const std::string& word, int line, const char* what) {
  size_t used = 0;
  double v = 0;
  try {
    v = std::stod(word, &used);
  } catch (const std::exception&) {
    fail(line, std::string("expected a time in ms for ") + what + ", got '" + word + "'");
  }
  if (used != word.size() || !std::isfinite(v) || v < 0 || v > 1e9)
    fail(line, std::string("bad time '") + word + "' for " + what + " (ms, 0..1e9)");
  return v;
}

uint64_t to_us(double ms) { return static_cast<uint64_t>(std::llround(ms * 1000.0)); }

int parse_int(const std::string& word, int line, const char* what, int lo, int hi) {
  size_t used = 0;
  long v = 0;
  try {
    v = std::stol(word, &used);
  } catch (const std::exception&) {
    fail(line, std::string("expected an integer ") + what + ", got '" + word + "'");
  }
  if (used != word.size() || v < lo || v > hi)
    fail(line, std::string("bad ") + what + " '" + word + "' (" + std::to_string(lo) + ".." +
                   std::to_string(hi) + ")");
  return static_cast<int>(v);
}

}  // namespace

std::vector<KnobAction> parse_knob_script(const std::string& text) {
  std::vector<KnobAction> actions;
  std::istringstream in(text);
  std::string raw;
  uint64_t cursor = 0;
  int bounce_count = 0;
  uint64_t bounce_period = 300;
  int line_no = 0;
  while (std::getline(in, raw)) {
    ++line_no;
    if (auto hash = raw.find('#'); hash != std::string::npos) raw.resize(hash);
    std::istringstream words(raw);
    std::vector<std::string> w;
    for (std::string s; words >> s;) w.push_back(s);
    if (w.empty()) continue;
    const std::string& cmd = w[0];
    auto need = [&](size_t lo, size_t hi) {
      if (w.size() < lo || w.size() > hi) fail(line_no, "wrong number of arguments for '" + cmd + "'");
    };
    KnobAction a;
    a.start_us = cursor;
    a.bounce_count = bounce_count;
    a.bounce_period_us = bounce_period;
    a.script_line = line_no;
    if (cmd == "wait") {
      need(2, 2);
      cursor += to_us(parse_ms(w[1], line_no, "wait"));
    } else if (cmd == "at") {
      need(2, 2);
      const uint64_t t = to_us(parse_ms(w[1], line_no, "at"));
      if (t < cursor) fail(line_no, "'at " + w[1] + "' would go back in time");
      cursor = t;
    } else if (cmd == "turn") {
      need(3, 5);
      a.kind = KnobAction::Kind::turn;
      a.target = parse_int(w[1], line_no, "dial", 0, firmware::kDialCount - 1);
      a.detents = parse_int(w[2], line_no, "detent count", -10000, 10000);
      double every = 80;
      if (w.size() == 5 && w[3] == "every") every = parse_ms(w[4], line_no, "every");
      else if (w.size() != 3) fail(line_no, "expected 'turn <dial> <±detents> [every <ms>]'");
      if (every <= 0) fail(line_no, "'every' must be positive");
      a.duration_us = to_us(every);
      if (a.duration_us < 4) fail(line_no, "'every' below 4 us cannot hold four transitions");
      actions.push_back(a);
      cursor += a.duration_us * static_cast<uint64_t>(std::abs(a.detents));
    } else if (cmd == "press" || cmd == "release") {
      need(2, 2);
      a.kind = cmd == "press" ? KnobAction::Kind::press : KnobAction::Kind::release;
      a.target = parse_int(w[1], line_no, "button", 0, firmware::kButtonCount - 1);
      actions.push_back(a);
    } else if (cmd == "click") {
      need(2, 4);
      a.kind = KnobAction::Kind::press;
      a.target = parse_int(w[1], line_no, "button", 0, firmware::kButtonCount - 1);
      double hold = 80;
      if (w.size() == 4 && w[2] == "hold") hold = parse_ms(w[3], line_no, "hold");
      else if (w.size() != 2) fail(line_no, "expected 'click <button> [hold <ms>]'");
      actions.push_back(a);
      cursor += to_us(hold);
      a.kind = KnobAction::Kind::release;
      a.start_us = cursor;
      actions.push_back(a);
    } else if (cmd == "bounce") {
      need(2, 3);
      bounce_count = parse_int(w[1], line_no, "bounce count", 0, 100);
      if (w.size() == 3) bounce_period = to_us(parse_ms(w[2], line_no, "bounce period"));
      if (bounce_count > 0 && bounce_period == 0) fail(line_no, "bounce period must be positive");
    } else if (cmd == "glitch") {
      need(3, 4);
      a.kind = KnobAction::Kind::glitch;
      a.target = parse_int(w[1], line_no, "dial", 0, firmware::kDialCount - 1);
      if (w[2] == "a" || w[2] == "A") a.line = 0;
      else if (w[2] == "b" || w[2] == "B") a.line = 1;
      else fail(line_no, "glitch line must be 'a' or 'b', got '" + w[2] + "'");
      a.duration_us = to_us(w.size() == 4 ? parse_ms(w[3], line_no, "glitch width") : 0.5);
      if (a.duration_us == 0) fail(line_no, "glitch width must be positive");
      actions.push_back(a);
    } else {
      fail(line_no, "unknown command '" + cmd + "'");
    }
  }
  return actions;
}

}  // namespace weft::sim
