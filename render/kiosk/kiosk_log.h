#pragma once
// The kiosk's operator log lines: stderr, which systemd sends to the journal with their priority.
#include <string>

#include "journal/journal_log.h"

namespace weft {

inline void kiosk_log_info(const std::string& s) { log_line("weft run", LogPriority::info, s); }
inline void kiosk_log_warning(const std::string& s) { log_line("weft run", LogPriority::warning, s); }
inline void kiosk_log_error(const std::string& s) { log_line("weft run", LogPriority::error, s); }

}  // namespace weft
