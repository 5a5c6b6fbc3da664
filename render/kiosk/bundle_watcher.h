#pragma once
// Notices when the kiosk's bundle file is replaced, so that new content is shown without a
// restart. Watches the file's directory with inotify (the file itself may be replaced by a
// rename, which a watch on the old inode would not see) for events naming the file:
//   IN_MOVED_TO     an atomic replace (rsync, systemd-sysupdate, an HTTP pull: write a
//                   temporary beside it, then rename it over the bundle);
//   IN_CLOSE_WRITE  a writer that wrote it in place closed it (finished, or cut off);
//   IN_CREATE       a new file or hard link under the name;
//   IN_MODIFY       a writer is still writing: only postpones the report.
// poll() never blocks (the frame loop calls it every tick). It reports a change once the file's
// events have settled for `settle` (so a copy in progress is read when it is done, not at each
// write); a file created empty and not written yet is not reported (its writer's close will be).
#include <chrono>
#include <filesystem>
#include <optional>
#include <string>

namespace weft {

class BundleWatcher {
public:
  using Clock = std::chrono::steady_clock;

  // Throws std::system_error naming the directory when it cannot be watched.
  explicit BundleWatcher(std::filesystem::path bundle, std::chrono::milliseconds settle = std::chrono::milliseconds(150));
  ~BundleWatcher();
  BundleWatcher(const BundleWatcher&) = delete;
  BundleWatcher& operator=(const BundleWatcher&) = delete;

  struct Change {
    Clock::time_point first_event;  // when the first event of this change was read
    std::string events;             // what happened, e.g. "moved into place", "written and closed"
  };
  // A settled change of the bundle file, if there is one.
  std::optional<Change> poll(Clock::time_point now = Clock::now());

  const std::filesystem::path& bundle() const { return bundle_; }
  const std::filesystem::path& directory() const { return directory_; }

private:
  void read_events(Clock::time_point now);

  std::filesystem::path bundle_, directory_;
  std::string name_;
  std::chrono::milliseconds settle_;
  int fd_ = -1;
  // The change being collected.
  std::optional<Clock::time_point> first_, last_;
  bool triggered_ = false;   // a move, close or create was seen (a modify alone is not a change)
  bool only_created_ = true; // nothing but IN_CREATE so far
  std::string events_;
};

}  // namespace weft
