// A facet's horizon (iwasaki.cpp's facet_horizon_factor): the share of SG k the plane of the
// triangle drawn at a fragment lets through beside the shading normal's. Read by iwasaki.glsl (per
// pixel) and iwasaki_vertex.frag (per vertex, each SG's interpolated radiance). Needs erf.glsl before it.

// core's sg_hemisphere_terms and sg_hemisphere_fraction: the share of an SG of sharpness λ above a
// plane at cos c from its axis, with the factors of λ alone, (t, 1/erf(t) or 0, e^{−λ}), apart.
vec3 sg_hemisphere_terms(float lambda) {
  const float A = 0.6517328826907056, B = 1.3418280033141288, C = 7.2216687798956709;
  float t = lambda * sqrt((0.5 * lambda + A) / ((lambda + B) * lambda + C));
  return vec3(t, t < 1e-6 ? 0.0 : 1.0 / erf_nr(t), exp(-lambda));
}
float sg_hemisphere_fraction_terms(vec3 terms, float c) {
  c = clamp(c, -1.0, 1.0);
  float factor = terms.y == 0.0 ? 0.5 + 0.5 * c : 0.5 + 0.5 * erf_nr(terms.x * c) * terms.y;
  float e = terms.z;
  return (e + (1.0 - e) * factor) / (1.0 + e);
}
float sg_hemisphere_fraction(float lambda, float c) { return sg_hemisphere_fraction_terms(sg_hemisphere_terms(lambda), c); }

// The plane of the triangle drawn at this fragment (from the position's screen derivatives), facing
// the eye; zero where the derivatives are degenerate.
vec3 facet_normal(vec3 position, vec3 eye) {
  vec3 c = cross(dFdx(position), dFdy(position));
  if (dot(c, c) <= 0.0) return vec3(0.0);
  return normalize(c) * (dot(c, eye - position) < 0.0 ? -1.0 : 1.0);
}

// min(1, H(λ, ξ·n_g)/H(λ, ξ·n_s)); 1 where the normals agree to 1e−4 or n_g is zero.
// `terms`: sg_hemisphere_terms(λ), taken once per lobe where many fragments cut the same one.
float facet_horizon_factor_terms(vec3 terms, vec3 axis, vec3 ns, vec3 ng) {
  if (ng == vec3(0.0) || dot(ns, ng) > 1.0 - 1e-4) return 1.0;
  float shading = sg_hemisphere_fraction_terms(terms, dot(axis, ns));
  float facet = sg_hemisphere_fraction_terms(terms, dot(axis, ng));
  return shading > 0.0 ? min(1.0, facet / shading) : 1.0;
}
float facet_horizon_factor(float lambda, vec3 axis, vec3 ns, vec3 ng) {
  return facet_horizon_factor_terms(sg_hemisphere_terms(lambda), axis, ns, ng);
}
