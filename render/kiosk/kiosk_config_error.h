#pragma once
// What the kiosk library throws for bad configuration (a bad flag value, an unreadable or
// malformed panel config or knob script): the `weft` commands turn it into exit code 2. The
// message names the flag, as the command line spelled it.
#include <stdexcept>
#include <string>

namespace weft {

class KioskConfigError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

// The whole of a file a flag names; KioskConfigError "<flag>: cannot open '<path>'".
std::string read_config_file(const std::string& path, const std::string& flag);

}  // namespace weft
