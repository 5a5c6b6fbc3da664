#pragma once
// libjpeg's error manager for Weft: its default error_exit calls exit(), which would take a
// kiosk or `weft capture` down over one bad file. This one longjmps back to the caller's setjmp
// with the library's message, and counts a premature end of data (libjpeg warns and pads the
// image with grey) as an error too, so a truncated file is refused rather than half-decoded.
// Private to render/image's JPEG code.
#include <csetjmp>
#include <cstdio>

#include <jpeglib.h>

namespace weft::jpeg_detail {

struct ErrorManager {
  jpeg_error_mgr manager;
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX] = {};
};

// Sets `info`'s err to `error`, installing the handlers above. The caller then does
// `if (setjmp(error.jump)) { destroy; throw ...(error.message); }` before any libjpeg call, and
// keeps objects with destructors out of the span between setjmp and the last libjpeg call.
void install(jpeg_common_struct* info, ErrorManager& error);

}  // namespace weft::jpeg_detail
