#include "panel/knob_source.h"

namespace weft::input {

LogSink stderr_log() { return stderr_sink("weft panel"); }

}  // namespace weft::input
