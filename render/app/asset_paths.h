#pragma once
// Where the data files (fabrics, scenes, envmaps) are, in this order:
//  1. $WEFT_ASSETS, when set;
//  2. the install prefix's share/weft, found from this executable's own location
//     (/proc/self/exe: <prefix>/bin/weft or <prefix>/libexec/weft/weft-offline);
//  3. the source tree's assets/ (running from a build folder).
#include <filesystem>

namespace weft {
std::filesystem::path assets_dir();
}
