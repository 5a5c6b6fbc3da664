// libFuzzer target for fabric files: any text either parses into a fabric that keeps
// the loader's promises (finite, physical, a_1 + a_2 ≤ 1, a usable tangent curve) or raises a
// FabricError; nothing else may escape, crash or read out of bounds.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/fabric.h"

namespace {

bool finite_non_negative(double x) { return std::isfinite(x) && x >= 0.0; }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const weft::Fabric f = weft::parse_fabric(text, "fuzz.json");
    double coverage = 0.0;
    for (const weft::ThreadParams& t : f.threads) {
      for (int c = 0; c < 3; ++c)
        if (!finite_non_negative(t.albedo[c])) __builtin_trap();
      if (!(t.eta > 1.0) || !std::isfinite(t.eta)) __builtin_trap();
      if (!(t.gamma_s > 0.0) || !(t.gamma_v > 0.0) || !std::isfinite(t.gamma_s) || !std::isfinite(t.gamma_v))
        __builtin_trap();
      if (!(t.kd >= 0.0 && t.kd <= 1.0)) __builtin_trap();
      if (!finite_non_negative(t.coverage)) __builtin_trap();
      coverage += t.coverage;
      // The curve must give samples: a fabric that loads must be renderable.
      for (double alpha : t.curve.sample_tilts(4))
        if (!std::isfinite(alpha)) __builtin_trap();
    }
    if (coverage > 1.0 + 1e-9) __builtin_trap();
  } catch (const weft::FabricError&) {
    // The expected outcome for almost every input.
  }
  return 0;
}
