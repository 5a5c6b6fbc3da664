#include "kiosk/kiosk_status_file.h"

#include <sys/stat.h>

#include <cstdlib>
#include <fstream>
#include <system_error>

#include "files/atomic_file.h"
#include "kiosk/kiosk_log.h"

namespace weft {
namespace {

// What, changed, is news to a fleet at once (the frame counts change every frame).
bool same_shown(const KioskStatus& a, const KioskStatus& b) {
  return a.state == b.state && a.bundle == b.bundle && a.last_good == b.last_good && a.scene == b.scene &&
         a.method == b.method && a.display == b.display && a.probe == b.probe &&
         a.content_update_at == b.content_update_at && a.content_update == b.content_update;
}

}  // namespace

std::filesystem::path default_status_path() {
  const char* runtime = std::getenv("RUNTIME_DIRECTORY");  // systemd: the first RuntimeDirectory
  std::string dir = runtime && *runtime ? runtime : "/run/weft";
  if (const auto colon = dir.find(':'); colon != std::string::npos) dir.resize(colon);
  return std::filesystem::path(dir) / "status.json";
}

StatusFile::StatusFile(std::filesystem::path path, std::chrono::milliseconds every)
    : path_(std::move(path)), every_(every) {}

void StatusFile::update(KioskStatus s, Clock::time_point now) {
  if (last_ && now - last_at_ < every_ && same_shown(*last_, s)) return;
  write(std::move(s), now);
}

void StatusFile::write(KioskStatus s, Clock::time_point now) {
  const double seconds = std::chrono::duration<double>(now - last_at_).count();
  s.fps = last_ && seconds > 0 ? double(s.drawn - last_->drawn) / seconds : 0.0;
  const std::string text = status_json(s);
  try {
    write_file_atomically(path_, [&](const std::filesystem::path& temporary) {
      std::ofstream out(temporary, std::ios::binary);
      out << text;
      out.close();
      if (!out) throw std::system_error(errno, std::generic_category(), "writing " + temporary.string());
      ::chmod(temporary.c_str(), 0644);  // the service's umask is 0077; operators read this file
    });
    if (failing_) kiosk_log_info("status file " + path_.string() + " written again");
    failing_ = false;
  } catch (const std::exception& e) {
    if (!failing_) kiosk_log_warning(std::string("status file not written: ") + e.what() + " (retried every few seconds)");
    failing_ = true;
  }
  last_ = std::move(s);
  last_at_ = now;
}

}  // namespace weft
