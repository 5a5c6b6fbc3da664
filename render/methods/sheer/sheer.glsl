// Methods `sheer` and `sheer_vertex` (methods/sheer/sheer.h): the thin layer (thin.glsl)
// over iwasaki (iwasaki.glsl): this file gives thin.glsl its thin_reflection() (iwasaki_radiance
// with its visibility) and thin_light_visibility() (the baked SDF's share of each SG on the mesh
// normal's side, 1 on the other). Mirrors methods/sheer/sheer.cpp. Needs microcylinder.glsl,
// erf.glsl, sg_lighting.glsl, hemisphere_grid.glsl, iwasaki.glsl and thin.glsl before it; the
// caller sets the point below, then calls thin_radiance().
vec3 sheer_position;       // the cloth point
vec3 sheer_mesh_normal;    // its interpolated mesh normal, unflipped (the side the bake cast from)
vec3 sheer_warp;
ivec3 sheer_corners;       // the SDF corners and weights, as iwasaki_radiance takes them
vec3 sheer_bary;

vec3 thin_reflection(vec3 n, vec3 u, vec3 wo) {
  iwasaki_behind = dot(sheer_mesh_normal, wo) < 0.0;  // n faces the eye already
  return iwasaki_radiance(sheer_position, n, u, sheer_corners, sheer_bary);
}

// sheer.cpp's sheer_sdf_share for SG k.
float sheer_sdf_share(int k) {
  vec3 s = sheer_bary.x * sg_visibility(sheer_corners.x, k);
  if (sheer_bary.y != 0.0 || sheer_bary.z != 0.0)
    s += sheer_bary.y * sg_visibility(sheer_corners.y, k) + sheer_bary.z * sg_visibility(sheer_corners.z, k);
  vec3 n = normalize(sheer_mesh_normal);
  vec3 u = normalize(sheer_warp - dot(sheer_warp, n) * n);
  vec3 v = cross(n, u);
  vec3 w = normalize(u_sg_axis[k]);
  float wu = clamp(dot(w, u), -1.0, 1.0), wn = dot(w, n), wv = dot(w, v);
  float theta = atan(wu, sqrt(max(wn * wn + wv * wv, 1e-8))), phi = atan(wv, wn);
  float sigma = u_sg_sigma[k];
  float sp = sigma / sqrt(max(cos(theta) * cos(theta), 1e-6));
  float h = visibility_h(sigma, sp, s);
  float horizon = horizon_h(theta, phi, sigma, sp, vec3(0.0, 1.0, 0.0));  // (t·n, n'·n, b·n) of the vertex frame
  return clamp(h / max(horizon, 1e-3), 0.0, 1.0);
}

vec2 thin_light_visibility(int k, vec3 n) {
  if (!u_visibility) return vec2(1.0);
  float share = sheer_sdf_share(k);
  return dot(n, sheer_mesh_normal) >= 0.0 ? vec2(share, 1.0) : vec2(1.0, share);
}
