// The weighting tables' direction grids (render/runtime/hemisphere_grid.h, whose comment gives the
// maps): a unit local direction → the node square [−1,1]², whose nodes sit at s = −1 + 2i/(n−1).
// One copy for iwasaki.glsl and mizutani.glsl; their parity tests pin it to the C++.
// Needs microcylinder.glsl (PI) before it.
const float NODE_RING_B = 1.84292037;  // 2 − kNodeRingHorizonSpacing·π/4 (hemisphere_grid.cpp's kRingB)

// Concentric square ↔ Lambert equal-area hemisphere (square_from_hemisphere).
vec2 square_from_hemisphere(vec3 w) {
  if (w.z < 0.0) {
    float h = length(w.xy);
    if (h == 0.0) return vec2(1.0, 0.0);
    w = vec3(w.xy / h, 0.0);
  }
  float r = length(w.xy) / sqrt(1.0 + w.z);  // = √(1 − z) for unit w, without cancellation at the zenith
  if (r == 0.0) return vec2(0.0);
  const float Q = 0.25 * PI;
  float phi = atan(w.y, w.x);
  if (phi < -Q) phi += 2.0 * PI;
  vec2 s;
  if (phi < Q) s = vec2(r, phi * r / Q);
  else if (phi < 3.0 * Q) s = vec2(-(phi - 2.0 * Q) * r / Q, r);
  else if (phi < 5.0 * Q) s = vec2(-r, (phi - PI) * -r / Q);
  else s = vec2(-(phi - 6.0 * Q) * -r / Q, -r);
  return clamp(s, vec2(-1.0), vec2(1.0));
}

// The node square: the ring at disk radius r moved to ρ with r = ρ(b − (b − 1)ρ)
// (node_square_from_hemisphere; square roots only, as there).
vec2 node_square_from_hemisphere(vec3 w) {
  vec2 s = square_from_hemisphere(w);
  float r = max(abs(s.x), abs(s.y));
  float rho_over_r = 2.0 / (NODE_RING_B + sqrt(max(0.0, NODE_RING_B * NODE_RING_B - 4.0 * (NODE_RING_B - 1.0) * r)));
  return clamp(s * rho_over_r, vec2(-1.0), vec2(1.0));
}
