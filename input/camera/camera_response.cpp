#include "camera/camera_response.h"

#include <algorithm>
#include <cmath>

namespace weft {

CameraResponse CameraResponse::srgb() {
  CameraResponse r;
  for (int z = 0; z < 256; ++z) {
    const double v = z / 255.0;
    r.inverse_table[z] = static_cast<float>(v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4));
  }
  return r;
}

uint8_t CameraResponse::encode(double linear) const {
  if (!(linear > 0.0)) return 0;
  if (linear >= 1.0) return 255;
  // The code whose linear value is nearest (the table is increasing): what an ISP's LUT does.
  const auto* end = inverse_table.data() + 256;
  const auto* it = std::lower_bound(inverse_table.data(), end, static_cast<float>(linear));
  if (it == end) return 255;
  if (it == inverse_table.data()) return 0;
  const auto* below = it - 1;
  return static_cast<uint8_t>((linear - *below < *it - linear ? below : it) - inverse_table.data());
}

bool CameraResponse::valid() const {
  if (!(inverse_table[0] >= 0.0f) || std::abs(inverse_table[255] - 1.0f) > 1e-6f) return false;
  for (int z = 1; z < 256; ++z)
    if (!(inverse_table[z] > inverse_table[z - 1])) return false;
  return true;
}

}  // namespace weft
