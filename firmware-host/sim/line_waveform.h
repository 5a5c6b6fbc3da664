#pragma once
// Knob actions → the contact edges the panel's lines would show (what a GPIO chip timestamps).
// Lines: dial d's A is line 2d, its B line 2d+1; button b is line 8+b. All lines idle high.
#include <cstdint>
#include <vector>

#include "sim/knob_script.h"

namespace weft::sim {

inline constexpr int kFirstButtonLine = 8;
inline constexpr int kLineCount = 8 + 5;

struct LineEdge {
  uint64_t time_us = 0;
  uint8_t line = 0;
  uint8_t level = 1;  // level after the edge
};

// Sorted by time (ties keep script order). Each turn detent is four single-line transitions
// spread evenly over its period; bounce adds chatter after every edge.
std::vector<LineEdge> line_edges(const std::vector<KnobAction>& actions);

}  // namespace weft::sim
