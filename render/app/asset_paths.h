#pragma once
// Where the data files are: $WEFT_ASSETS if set, else the source tree's assets/.
#include <filesystem>

namespace weft {
std::filesystem::path assets_dir();
}
