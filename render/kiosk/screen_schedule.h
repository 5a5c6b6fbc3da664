#pragma once
// When the kiosk's screen sleeps: a daily off period in local time ("22:00-07:30"; one that ends
// before it starts runs past midnight), during which the kiosk powers the display down (DPMS off)
// and draws nothing, and wakes it when the period ends.
#include <optional>
#include <string>

namespace weft {

class ScreenSchedule {
public:
  // "" : never off. Throws std::invalid_argument naming what is wrong ("HH:MM-HH:MM", hours 0–23,
  // minutes 0–59, start ≠ end).
  static ScreenSchedule parse(const std::string& text);
  bool empty() const { return !off_; }
  // Whether the screen is off at `minute_of_day` (0 … 1439, local time).
  bool off_at(int minute_of_day) const;
  std::string text() const;  // as given, normalised: "22:00-07:30"; "" when never

private:
  struct Period { int start, end; };  // minutes of the day
  std::optional<Period> off_;
};

// The local time's minute of the day now.
int local_minute_of_day();

}  // namespace weft
