// A facet's horizon (iwasaki.cpp's facet_horizon_factor): the share of SG k the plane of the
// triangle drawn at a fragment lets through beside the shading normal's. Read by iwasaki.glsl (per
// pixel) and iwasaki_vertex.frag (per vertex, each SG's interpolated radiance). Needs erf.glsl before it.

// core's sg_hemisphere_fraction: the share of an SG of sharpness λ above a plane at cos c from its axis.
float sg_hemisphere_fraction(float lambda, float c) {
  c = clamp(c, -1.0, 1.0);
  const float A = 0.6517328826907056, B = 1.3418280033141288, C = 7.2216687798956709;
  float t = lambda * sqrt((0.5 * lambda + A) / ((lambda + B) * lambda + C));
  float factor = t < 1e-6 ? 0.5 + 0.5 * c : 0.5 + 0.5 * erf_nr(t * c) / erf_nr(t);
  float e = exp(-lambda);
  return (e + (1.0 - e) * factor) / (1.0 + e);
}

// The plane of the triangle drawn at this fragment (from the position's screen derivatives), facing
// the eye; zero where the derivatives are degenerate.
vec3 facet_normal(vec3 position, vec3 eye) {
  vec3 c = cross(dFdx(position), dFdy(position));
  if (dot(c, c) <= 0.0) return vec3(0.0);
  return normalize(c) * (dot(c, eye - position) < 0.0 ? -1.0 : 1.0);
}

// min(1, H(λ, ξ·n_g)/H(λ, ξ·n_s)); 1 where the normals agree to 1e−4 or n_g is zero.
float facet_horizon_factor(float lambda, vec3 axis, vec3 ns, vec3 ng) {
  if (ng == vec3(0.0) || dot(ns, ng) > 1.0 - 1e-4) return 1.0;
  float shading = sg_hemisphere_fraction(lambda, dot(axis, ns));
  float facet = sg_hemisphere_fraction(lambda, dot(axis, ng));
  return shading > 0.0 ? min(1.0, facet / shading) : 1.0;
}
