// erf and erfc for GLSL ES, which has neither: Numerical Recipes' Chebyshev fit of erfc,
// fractional error < 1.2e-7 (the C++ twins use std::erf / std::erfc). Used by sg_lighting.glsl
// and iwasaki.glsl; mizutani.glsl keeps its own erf, the one its C++ side uses.
float erfc_nr_tail(float z) {  // erfc(z) for z ≥ 0
  float t = 1.0 / (1.0 + 0.5 * z);
  return t * exp(-z * z - 1.26551223 + t * (1.00002368 + t * (0.37409196 + t * (0.09678418 +
         t * (-0.18628806 + t * (0.27886807 + t * (-1.13520398 + t * (1.48851587 +
         t * (-0.82215223 + t * 0.17087277)))))))));
}
float erfc_nr(float x) {
  float r = erfc_nr_tail(abs(x));
  return x >= 0.0 ? r : 2.0 - r;
}
float erf_nr(float x) {
  float r = erfc_nr_tail(abs(x));
  return x >= 0.0 ? 1.0 - r : r - 1.0;
}
