#include "kiosk/kiosk_config_error.h"

#include <fstream>
#include <sstream>

namespace weft {

std::string read_config_file(const std::string& path, const std::string& flag) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw KioskConfigError(flag + ": cannot open '" + path + "'");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace weft
