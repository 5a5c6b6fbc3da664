// libFuzzer target for environment maps: any bytes, written to a file as the kiosk
// would find them, either load into a map whose texels are finite and non-negative (NaN/Inf/
// negative texels clamped, as `--non-finite clamp` does) or raise an EnvMapError. Exceptions
// from OpenEXR itself must not escape the loader.
#include <unistd.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "lighting/env_map.h"

namespace {

const std::filesystem::path& scratch_file() {
  static const std::filesystem::path p =
      std::filesystem::temp_directory_path() / ("weft_exr_fuzz_" + std::to_string(::getpid()) + ".exr");
  return p;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  {
    std::ofstream out(scratch_file(), std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    weft::EnvMapRepairs repairs;
    const weft::EnvMap map = weft::load_env_map(scratch_file(), weft::NonFinitePolicy::clamp, &repairs);
    if (map.width <= 0 || map.height <= 0) __builtin_trap();
    if (map.texels.size() != static_cast<std::size_t>(map.width) * static_cast<std::size_t>(map.height))
      __builtin_trap();
    for (const glm::vec3& p : map.texels)
      for (int c = 0; c < 3; ++c)
        if (!std::isfinite(p[c]) || p[c] < 0) __builtin_trap();
  } catch (const weft::EnvMapError&) {
    // The expected outcome for almost every input.
  }
  return 0;
}
