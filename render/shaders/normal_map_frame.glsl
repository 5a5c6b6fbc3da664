// A cloth's normal map as seed 002 applies it: n perturbed to n' and the thread frame turned by the
// rotation that takes n to n', so the threads stay in the perturbed surface. Mirrors
// core/normal_map_frame.h (tangent_space_normal, normal_mapped_frame).
vec3 tangent_space_normal(vec3 texel, float scale) {
  vec3 t = 2.0 * texel - 1.0;
  // 8-bit flat codes (127, 128) read as 0: core/normal_map_frame.h.
  t.xy = scale * sign(t.xy) * max(abs(t.xy) - 1.0 / 255.0, 0.0) / (1.0 - 1.0 / 255.0);
  t.z = max(t.z, 1e-3);
  return normalize(t);
}
// Turns (n, u) (unit, u ⟂ n) in place: n to n' = t.x·u + t.y·(n × u) + t.z·n, u with it.
void normal_mapped_frame(inout vec3 n, inout vec3 u, vec3 t) {
  vec3 v = cross(n, u);
  float d = 1.0 / (1.0 + t.z);
  vec3 ru = vec3(1.0 - t.x * t.x * d, -t.x * t.y * d, -t.x);
  vec3 nn = normalize(t.x * u + t.y * v + t.z * n);
  u = normalize(ru.x * u + ru.y * v + ru.z * n);
  n = nn;
}
