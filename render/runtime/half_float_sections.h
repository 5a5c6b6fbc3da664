#pragma once
// Float tables stored as IEEE binary16 (bundle ElementType::F16) where 11 significant bits are
// far below the error they were fitted to (the weighting tables' factors, the visibility PCA's
// basis): half the bytes of the bundle's largest sections. Imath's half does the rounding (to
// nearest even) and the decoding.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "bundle/bundle_reader.h"
#include "bundle/bundle_writer.h"

namespace weft {

// `values` as an f16 section when every one is finite and within binary16's range (±65504), else
// as f32 (nothing is lost to an overflow).
void add_halves_or_floats(bundle::BundleWriter& w, const std::string& name, std::span<const float> values,
                          std::vector<std::uint64_t> shape);

// An f32 or f16 section's values as floats; bundle::BundleError when it is absent or of another type.
std::vector<float> read_halves_or_floats(const bundle::BundleReader& r, const std::string& name);

}  // namespace weft
