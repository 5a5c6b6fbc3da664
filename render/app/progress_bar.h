#pragma once
// A one-line progress bar on stderr, redrawn in place: "label [#####.....]  48%  12.0 s".
// When stderr is not a terminal (a log file, the journal, CI) it prints a line every 10 % instead:
// '\r' redraws would pile a stage's hundred frames into one line there.
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>

namespace weft {

class ProgressBar {
public:
  explicit ProgressBar(std::string label) : label_(std::move(label)), start_(std::chrono::steady_clock::now()) {}
  void operator()(double fraction) {
    const int percent = static_cast<int>(std::lround(100.0 * fraction));
    if (percent == last_ || (!terminal_ && last_ >= 0 && percent / 10 == last_ / 10 && percent < 100)) return;
    last_ = percent;
    const int filled = percent * 30 / 100;
    std::fprintf(stderr, "%s%s [%s%s] %3d%% %6.1f s", terminal_ ? "\r" : "", label_.c_str(),
                 std::string(filled, '#').c_str(), std::string(30 - filled, '.').c_str(), percent, seconds());
    if (percent >= 100 || !terminal_) std::fprintf(stderr, "\n");
    std::fflush(stderr);
  }
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

private:
  std::string label_;
  std::chrono::steady_clock::time_point start_;
  int last_ = -1;
  bool terminal_ = isatty(fileno(stderr)) != 0;
};

// A bar for one stage, as the bakers' per-stage progress callbacks (bake/scene/scene_bake.h) open them.
inline std::function<void(double)> open_progress_bar(const std::string& label) {
  auto bar = std::make_shared<ProgressBar>(label);
  return [bar](double fraction) { (*bar)(fraction); };
}

}  // namespace weft
