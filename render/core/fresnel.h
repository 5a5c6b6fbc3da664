#pragma once
// Exact unpolarised Fresnel reflectance of a smooth dielectric boundary (outside index 1,
// inside η), as the microcylinder model uses it.
namespace weft {

// cos_i: cosine of the incidence angle, clamped to [0, 1]. η > 0.
double fresnel_dielectric(double eta, double cos_i);

}  // namespace weft
