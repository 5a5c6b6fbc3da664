#pragma once
// Numbers as the bench's logs, CSVs and report print them: printf's %g with `digits` significant digits.
#include <cstdio>
#include <string>

namespace weft::bench {

inline std::string fmt(double x, int digits = 3) {
  char b[64];
  std::snprintf(b, sizeof b, "%.*g", digits, x);
  return b;
}

}  // namespace weft::bench
