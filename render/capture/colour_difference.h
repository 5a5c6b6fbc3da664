#pragma once
// How far apart two colours look: CIE L*a*b* under D65 and the CIEDE2000 difference, the measure
// of a fitted thread colour against the truth (ΔE2000 ≤ 3: hard to tell apart side by side).
// The difference formula is Little CMS's (cmsCIE2000DeltaE), pinned to Sharma, Wu and Dalal's
// test data (Color Res. Appl. 30(1), 2005) by tests/capture/colour_difference_test.cpp.
#include <glm/vec3.hpp>

namespace weft {

struct Lab {
  double L = 0, a = 0, b = 0;
};

// Linear sRGB (Rec. 709 primaries, D65 white; the model's albedos) → CIE L*a*b* relative to the
// D65 white at Y = 1.
Lab lab_from_linear_srgb(const glm::dvec3& rgb);

// CIEDE2000 with k_L = k_C = k_H = 1.
double delta_e2000(const Lab& x, const Lab& y);

// ΔE2000 between two linear sRGB colours.
double delta_e2000(const glm::dvec3& x, const glm::dvec3& y);

}  // namespace weft
