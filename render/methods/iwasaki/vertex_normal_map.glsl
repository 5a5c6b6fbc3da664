// A normal map on the per-vertex rungs (iwasaki_vertex.frag). The vertices shade the surface's own
// frame and hold no texel, so per pixel each SG's interpolated split (surface, warp volume, weft
// volume) is multiplied by the SG's response in the frame the map turns (normal_map_frame.glsl)
// over its response in the surface's frame. A response: the model under a point light at ω*, per
// unit cosine n·ω*, times the SG's clamped-cosine integral E(λ, ξ·n); ω* is the SG's axis, lifted
// where the lobe's mean cosine over the hemisphere (sg_effective_cosine) is higher than the axis's
// (a lobe low, broad or below the horizon lights the surface from above its axis). Each lobe is
// widened by the SG's spread as the weave layer's ratio is (u_sg_widen2 = weave_lobe_widening(λ_k)).
// So a narrow lobe above the horizon is a point light at its axis, and a lobe the bump tilts
// towards the horizon fades with its cosine-weighted share instead of stepping to zero.
// Part by part: each part is per unit albedo, so the ratio holds for any knob colour or texel, and
// each SG keeps the visibility the rung gave it. Each part's ratio is (bumped + ε)/(surface + ε),
// ε = NORMAL_MAP_RATIO_BIAS, capped at NORMAL_MAP_RATIO_CAP: 1 where neither frame responds, and
// continuous where a grazing lobe's responses are tiny. Needs microcylinder.glsl, erf.glsl,
// sg_lighting.glsl, normal_map_frame.glsl and cloth_normal_map.glsl before it.
// C++ twin: methods/iwasaki/vertex_normal_map.h.
uniform float u_sg_widen2[MAX_SGS];

vec3 normal_map_lobe_response(vec3 n, vec3 u, vec3 axis, vec3 wo, float lambda, float widen2) {
  float c = dot(axis, n);
  vec3 wi = lift_to_cosine(axis, n, sg_effective_cosine(lambda, c));
  return sg_clamped_cosine_integral(lambda, c) / max(dot(n, wi), SG_HORIZON_COSINE) *
         cloth_integrand_split_widened(n, u, wi, wo, widen2);
}

vec3 normal_map_lobe_ratio(vec3 n, vec3 u, vec3 nb, vec3 ub, vec3 axis, vec3 wo, float lambda, float widen2) {
  vec3 surface = normal_map_lobe_response(n, u, axis, wo, lambda, widen2);
  vec3 bumped = normal_map_lobe_response(nb, ub, axis, wo, lambda, widen2);
  vec3 r;
  for (int c = 0; c < 3; ++c)
    r[c] = min((bumped[c] + NORMAL_MAP_RATIO_BIAS) / (surface[c] + NORMAL_MAP_RATIO_BIAS), NORMAL_MAP_RATIO_CAP);
  return r;
}

// The cheap ratio for the SGs beyond the two that light a pixel most (iwasaki_vertex.frag): the
// clamped-cosine integrals' E(λ, ξ·nb)/E(λ, ξ·n), on every part, biased by NORMAL_MAP_RATIO_BIAS
// of E(λ, 1) and capped alike.
vec3 normal_map_cosine_ratio(vec3 n, vec3 nb, vec3 axis, float lambda) {
  float bias = NORMAL_MAP_RATIO_BIAS * sg_clamped_cosine_integral(lambda, 1.0);
  float r = (sg_clamped_cosine_integral(lambda, dot(axis, nb)) + bias) / (sg_clamped_cosine_integral(lambda, dot(axis, n)) + bias);
  return vec3(min(r, NORMAL_MAP_RATIO_CAP));
}

// Whether the tangent-space normal t tilts at all: a flat texel (8-bit 127/128 codes read within
// float rounding of 0) skips the ratio, so a flat map draws exactly the unmapped image.
bool normal_map_tilts(vec3 t) { return max(abs(t.x), abs(t.y)) >= NORMAL_MAP_FLAT_TILT; }
