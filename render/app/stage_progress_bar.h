#pragma once
// `weft bake-tables`' progress: one bar for the stages the table baker reports, with the
// stage's name after it: "[#####.....]  48%  G·W products". Redrawn in place on a terminal;
// on a log (not a terminal) only every 10 % or when the stage changes.
#include <unistd.h>

#include <cstdio>
#include <string>
#include <string_view>

namespace weft {

class StageProgressBar {
public:
  void operator()(double f, std::string_view stage) {
    const int pct = static_cast<int>(f * 100.0 + 0.5);
    if (pct == last_ && stage == stage_) return;
    const bool tty = isatty(STDERR_FILENO);
    if (!tty && pct / 10 == last_ / 10 && stage == stage_) return;
    last_ = pct;
    stage_ = std::string(stage);
    const int width = 30, filled = pct * width / 100;
    std::string bar(filled, '#');
    bar.resize(width, '.');
    std::fprintf(stderr, tty ? "\r[%s] %3d%%  %-40s" : "[%s] %3d%%  %s\n", bar.c_str(), pct, stage_.c_str());
    if (pct >= 100 && tty) std::fprintf(stderr, "\n");
    std::fflush(stderr);
  }

private:
  int last_ = -1;
  std::string stage_;
};

}  // namespace weft
