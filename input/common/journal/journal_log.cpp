#include "journal/journal_log.h"

#include <sys/stat.h>
#include <systemd/sd-daemon.h>

#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <mutex>

namespace weft {

namespace {

const char* sd_prefix(LogPriority p) {
  switch (p) {
    case LogPriority::error: return SD_ERR;
    case LogPriority::warning: return SD_WARNING;
    case LogPriority::info: break;
  }
  return SD_INFO;
}

}  // namespace

bool stderr_is_journal() {
  const char* stream = std::getenv("JOURNAL_STREAM");
  if (!stream || !*stream) return false;
  uintmax_t dev = 0, ino = 0;
  if (std::sscanf(stream, "%" SCNuMAX ":%" SCNuMAX, &dev, &ino) != 2) return false;
  struct stat st {};
  if (::fstat(2, &st) != 0) return false;
  return static_cast<uintmax_t>(st.st_dev) == dev && static_cast<uintmax_t>(st.st_ino) == ino;
}

std::string format_log_line(std::string_view tag, LogPriority priority, std::string_view text, bool journal) {
  std::string line = journal ? sd_prefix(priority) : "";
  line.append(tag).append(": ").append(text);
  return line;
}

void log_line(std::string_view tag, LogPriority priority, std::string_view text) {
  // Threads (knob sources, the probe worker, the frame loop) log concurrently: whole lines only.
  static std::mutex m;
  const std::string line = format_log_line(tag, priority, text, stderr_is_journal()) + "\n";
  std::lock_guard lock(m);
  std::fwrite(line.data(), 1, line.size(), stderr);
  std::fflush(stderr);
}

LogSink stderr_sink(std::string tag) {
  return [tag = std::move(tag)](LogPriority p, const std::string& text) { log_line(tag, p, text); };
}

}  // namespace weft
