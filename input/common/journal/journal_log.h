#pragma once
// Operator log lines: "<tag>: <text>" on stderr, one line per call. When stderr is the journal
// (systemd sets JOURNAL_STREAM to its device:inode, systemd.exec(5)), each line starts with the
// sd-daemon(3) priority prefix ("<3>" error, "<4>" warning, "<6>" info) so
// `journalctl -p warning` finds the warnings; on a terminal or in a file the text is unprefixed.
#include <functional>
#include <string>
#include <string_view>

namespace weft {

enum class LogPriority { error, warning, info };

// Where log lines go (one line per call, no trailing newline).
using LogSink = std::function<void(LogPriority, const std::string&)>;

// True when JOURNAL_STREAM names the file stderr is open on.
bool stderr_is_journal();

// The line as written, without the newline: "[<N>]<tag>: <text>".
std::string format_log_line(std::string_view tag, LogPriority priority, std::string_view text, bool journal);

// Writes one line to stderr and flushes it.
void log_line(std::string_view tag, LogPriority priority, std::string_view text);

// A sink that writes under `tag` (e.g. "weft run").
LogSink stderr_sink(std::string tag);

}  // namespace weft
