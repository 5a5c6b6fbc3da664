#include "sim/line_waveform.h"

#include <algorithm>
#include <array>

namespace weft::sim {
namespace {

void add_edge(std::vector<LineEdge>& out, uint64_t t, int line, uint8_t level, const KnobAction& a) {
  out.push_back({t, static_cast<uint8_t>(line), level});
  for (int i = 1; i <= a.bounce_count; ++i) {
    out.push_back({t + (2 * i - 1) * a.bounce_period_us, static_cast<uint8_t>(line),
                   static_cast<uint8_t>(!level)});
    out.push_back({t + 2 * i * a.bounce_period_us, static_cast<uint8_t>(line), level});
  }
}

}  // namespace

std::vector<LineEdge> line_edges(const std::vector<KnobAction>& actions) {
  std::array<uint8_t, kLineCount> level;
  level.fill(1);
  std::vector<LineEdge> out;
  for (const KnobAction& a : actions) {
    switch (a.kind) {
      case KnobAction::Kind::turn: {
        const int la = 2 * a.target, lb = la + 1;
        const int n = 4 * std::abs(a.detents);
        const uint64_t quarter = a.duration_us / 4;
        if (2 * a.bounce_count * a.bounce_period_us >= quarter)
          throw ScriptError("script line " + std::to_string(a.script_line) +
                            ": contact bounce outlasts the time between transitions of this turn "
                            "(use a slower turn or shorter bounce)");
        for (int k = 0; k < n; ++k) {
          // Clockwise Gray order 00→01→11→10: flip B when A == B, else A; reversed for ccw.
          const bool same = level[la] == level[lb];
          const int flip = (a.detents > 0) == same ? lb : la;
          level[flip] = !level[flip];
          add_edge(out, a.start_us + k * quarter + quarter / 2, flip, level[flip], a);
        }
        break;
      }
      case KnobAction::Kind::press:
      case KnobAction::Kind::release: {
        const int line = kFirstButtonLine + a.target;
        const uint8_t target = a.kind == KnobAction::Kind::press ? 0 : 1;
        if (level[line] == target) break;  // already there: no edge
        level[line] = target;
        add_edge(out, a.start_us, line, target, a);
        break;
      }
      case KnobAction::Kind::glitch: {
        const int line = 2 * a.target + a.line;
        out.push_back({a.start_us, static_cast<uint8_t>(line), static_cast<uint8_t>(!level[line])});
        out.push_back({a.start_us + a.duration_us, static_cast<uint8_t>(line), level[line]});
        break;
      }
    }
  }
  std::stable_sort(out.begin(), out.end(),
                   [](const LineEdge& x, const LineEdge& y) { return x.time_us < y.time_us; });
  return out;
}

}  // namespace weft::sim
