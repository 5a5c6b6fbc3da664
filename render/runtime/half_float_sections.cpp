#include "runtime/half_float_sections.h"

#include <cmath>
#include <cstring>

#include <Imath/half.h>

namespace weft {

void add_halves_or_floats(bundle::BundleWriter& w, const std::string& name, std::span<const float> values,
                          std::vector<std::uint64_t> shape) {
  constexpr float kHalfMax = 65504.0f;
  for (float x : values)
    if (!std::isfinite(x) || std::abs(x) > kHalfMax) return w.add_array<float>(name, values, std::move(shape));
  std::vector<std::uint16_t> bits(values.size());
  for (size_t i = 0; i < values.size(); ++i) bits[i] = Imath::half(values[i]).bits();
  w.add_raw(name, bundle::ElementType::F16, std::move(shape), std::as_bytes(std::span<const std::uint16_t>(bits)));
}

std::vector<float> read_halves_or_floats(const bundle::BundleReader& r, const std::string& name) {
  if (r.has(name) && r.section(name).type == bundle::ElementType::F16) {
    const std::span<const std::byte> raw = r.raw(name);
    std::vector<float> out(raw.size() / 2);
    for (size_t i = 0; i < out.size(); ++i) {
      std::uint16_t b = 0;
      std::memcpy(&b, raw.data() + 2 * i, 2);
      Imath::half h;
      h.setBits(b);
      out[i] = float(h);
    }
    return out;
  }
  const auto a = r.array<float>(name);
  return {a.begin(), a.end()};
}

}  // namespace weft
