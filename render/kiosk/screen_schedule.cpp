#include "kiosk/screen_schedule.h"

#include <cstdio>
#include <ctime>
#include <stdexcept>

namespace weft {

namespace {
int minute_of(const std::string& hhmm, const std::string& whole) {
  int h = -1, m = -1;
  char tail = 0;
  if (hhmm.size() < 4 || std::sscanf(hhmm.c_str(), "%d:%d%c", &h, &m, &tail) != 2 || h < 0 || h > 23 || m < 0 || m > 59)
    throw std::invalid_argument("'" + whole + "': expected HH:MM-HH:MM in local time (hours 0-23, minutes 0-59), e.g. 22:00-07:30");
  return h * 60 + m;
}
std::string hhmm(int minute) {
  char s[24];
  std::snprintf(s, sizeof s, "%02d:%02d", minute / 60, minute % 60);
  return s;
}
}  // namespace

ScreenSchedule ScreenSchedule::parse(const std::string& text) {
  ScreenSchedule s;
  if (text.empty()) return s;
  const auto dash = text.find('-');
  if (dash == std::string::npos)
    throw std::invalid_argument("'" + text + "': expected HH:MM-HH:MM in local time, e.g. 22:00-07:30");
  const int start = minute_of(text.substr(0, dash), text), end = minute_of(text.substr(dash + 1), text);
  if (start == end) throw std::invalid_argument("'" + text + "': the off period starts and ends at the same time");
  s.off_ = Period{start, end};
  return s;
}

bool ScreenSchedule::off_at(int minute) const {
  if (!off_) return false;
  if (off_->start < off_->end) return minute >= off_->start && minute < off_->end;
  return minute >= off_->start || minute < off_->end;  // past midnight
}

std::string ScreenSchedule::text() const { return off_ ? hhmm(off_->start) + "-" + hhmm(off_->end) : ""; }

int local_minute_of_day() {
  const std::time_t now = std::time(nullptr);
  std::tm local{};
  localtime_r(&now, &local);
  return local.tm_hour * 60 + local.tm_min;
}

}  // namespace weft
