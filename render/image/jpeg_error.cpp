#include "image/jpeg_error.h"

#include <jerror.h>

namespace weft::jpeg_detail {

namespace {

[[noreturn]] void fail(j_common_ptr info) {
  auto* e = reinterpret_cast<ErrorManager*>(info->err);
  (*info->err->format_message)(info, e->message);
  std::longjmp(e->jump, 1);
}

// Level −1 is a warning: most (extraneous bytes before a marker, as some cameras write) decode
// fine and are ignored; the end of the data before the image's end is a truncated file.
void message(j_common_ptr info, int level) {
  if (level == -1 && info->err->msg_code == JWRN_JPEG_EOF) fail(info);
}

}  // namespace

void install(jpeg_common_struct* info, ErrorManager& error) {
  info->err = jpeg_std_error(&error.manager);
  error.manager.error_exit = fail;
  error.manager.emit_message = message;
}

}  // namespace weft::jpeg_detail
