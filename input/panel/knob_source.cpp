#include "panel/knob_source.h"

#include <cstdio>

namespace weft::input {

LogSink stderr_log() {
  return [](const std::string& line) { std::fprintf(stderr, "weft panel: %s\n", line.c_str()); };
}

}  // namespace weft::input
