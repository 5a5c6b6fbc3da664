#pragma once
// Seconds elapsed since a steady-clock time point (bake, reference and run times in the report).
#include <chrono>

namespace weft::bench {

inline double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace weft::bench
