#pragma once
// Where and when the kiosk writes its status (kiosk/kiosk_status.h): atomically (a reader never
// sees half a file), readable by every user of the machine (it holds nothing secret), every few
// seconds and at once when what is shown changes.
#include <chrono>
#include <filesystem>
#include <optional>

#include "kiosk/kiosk_status.h"

namespace weft {

// $RUNTIME_DIRECTORY/status.json (the service's RuntimeDirectory, /run/weft), else
// /run/weft/status.json.
std::filesystem::path default_status_path();

class StatusFile {
public:
  using Clock = std::chrono::steady_clock;

  explicit StatusFile(std::filesystem::path path, std::chrono::milliseconds every = std::chrono::seconds(2));

  // Writes `s` when `every` has passed since the last write or what it shows differs from the
  // last written (state, bundle, scene, method, display, probe, content update). Fills s.fps:
  // frames drawn per second since the last write. A failure is logged once, until a write works.
  void update(KioskStatus s, Clock::time_point now);
  void write(KioskStatus s, Clock::time_point now);  // now, whatever changed

  const std::filesystem::path& path() const { return path_; }

private:
  std::filesystem::path path_;
  std::chrono::milliseconds every_;
  std::optional<KioskStatus> last_;
  Clock::time_point last_at_{};
  bool failing_ = false;
};

}  // namespace weft
