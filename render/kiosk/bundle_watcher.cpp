#include "kiosk/bundle_watcher.h"

#include <sys/inotify.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <system_error>

namespace weft {
namespace {

void add_event(std::string& events, const char* what) {
  if (events.find(what) != std::string::npos) return;
  if (!events.empty()) events += ", ";
  events += what;
}

}  // namespace

BundleWatcher::BundleWatcher(std::filesystem::path bundle, std::chrono::milliseconds settle)
    : bundle_(std::move(bundle)), settle_(settle) {
  directory_ = bundle_.parent_path();
  if (directory_.empty()) directory_ = ".";
  name_ = bundle_.filename().string();
  fd_ = inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
  if (fd_ < 0) throw std::system_error(errno, std::generic_category(), "inotify_init1");
  if (inotify_add_watch(fd_, directory_.c_str(), IN_MOVED_TO | IN_CLOSE_WRITE | IN_CREATE | IN_MODIFY | IN_ONLYDIR) < 0) {
    const int e = errno;
    ::close(fd_);
    fd_ = -1;
    throw std::system_error(e, std::generic_category(), "cannot watch " + directory_.string());
  }
}

BundleWatcher::~BundleWatcher() {
  if (fd_ >= 0) ::close(fd_);
}

void BundleWatcher::read_events(Clock::time_point now) {
  alignas(inotify_event) char buf[8192];
  for (;;) {
    const ssize_t n = ::read(fd_, buf, sizeof buf);
    if (n <= 0) return;  // EAGAIN: nothing more now
    for (ssize_t at = 0; at < n;) {
      const auto* ev = reinterpret_cast<const inotify_event*>(buf + at);
      at += ssize_t(sizeof(inotify_event) + ev->len);
      const bool overflow = ev->mask & IN_Q_OVERFLOW;  // events were lost: look at the file anyway
      if (!overflow && (ev->len == 0 || name_ != ev->name)) continue;
      if (!first_) first_ = now;
      last_ = now;
      if (overflow) add_event(events_, "events lost");
      if (ev->mask & IN_MOVED_TO) add_event(events_, "moved into place");
      if (ev->mask & IN_CLOSE_WRITE) add_event(events_, "written and closed");
      if (ev->mask & IN_CREATE) add_event(events_, "created");
      if (ev->mask & (IN_MOVED_TO | IN_CLOSE_WRITE | IN_Q_OVERFLOW)) only_created_ = false;
      if (ev->mask & (IN_MOVED_TO | IN_CLOSE_WRITE | IN_CREATE | IN_Q_OVERFLOW)) triggered_ = true;
    }
  }
}

std::optional<BundleWatcher::Change> BundleWatcher::poll(Clock::time_point now) {
  read_events(now);
  if (!triggered_ || now - *last_ < settle_) return std::nullopt;
  if (only_created_) {
    // Created and not yet written: its writer's close comes next.
    std::error_code ec;
    if (std::filesystem::is_regular_file(bundle_, ec) && std::filesystem::file_size(bundle_, ec) == 0 && !ec)
      return std::nullopt;
  }
  Change c{*first_, events_};
  first_.reset();
  last_.reset();
  triggered_ = false;
  only_created_ = true;
  events_.clear();
  return c;
}

}  // namespace weft
