// The broad lobes' quadrature at a mesh vertex (methods/iwasaki/broad_lobe_quadrature.cpp's
// broad_lobe_radiance): for each SG with u_sg_broad[k] = s + 1, its SgWarpedGrid of n × 2n cells,
// each open cell's direction weighted by the canonical model (cloth_integrand_split). Needs
// microcylinder.glsl and sg_lighting.glsl before it.
uniform int u_broad_grid;                  // n (kBroadLobeGrid)
uniform int u_broad_words_per_sg;          // kBroadLobeWordsPerSg
uniform highp usampler2D u_broad_bits;     // BroadLobeBits' words, 4 per RGBA32UI texel
uniform int u_broad_bits_per_row;          // vertices per texel row
uniform int u_broad_texels_per_vertex;

uint broad_word(int vertex, int word) {
  int p = u_broad_bits_per_row;
  ivec2 texel = ivec2((vertex - (vertex / p) * p) * u_broad_texels_per_vertex + word / 4, vertex / p);
  uvec4 w = texelFetch(u_broad_bits, texel, 0);
  int c = word - (word / 4) * 4;
  return c == 0 ? w.x : (c == 1 ? w.y : (c == 2 ? w.z : w.w));
}

// SG k's part at unit amplitude, split as cloth_integrand_split: (surface, thread 0's volume per
// unit albedo, thread 1's); zero for an SG that is not broad. The radiance is
// μ_k·(x + A_0·y + A_1·z): the per-vertex rungs keep the split, so the albedo (a knob, a texel)
// applies per pixel.
vec3 broad_lobe_split(int vertex, vec3 position, vec3 normal, vec3 warp, int k) {
  int slot = u_sg_broad[k] - 1;
  if (slot < 0) return vec3(0.0);
  vec3 n = normalize(normal);
  vec3 wo = normalize(u_eye - position);
  if (dot(n, wo) < 0.0) n = -n;  // as iwasaki_radiance: the side facing the eye
  vec3 u = normalize(warp - dot(warp, n) * n);
  float lambda = u_sg_sharpness[k];
  vec3 axis = u_sg_axis[k];
  ClothView view = cloth_view(n, u, wo);  // ω_o's part, the same in every cell
  vec3 lobe = vec3(0.0);
  int cells_per_row = 2 * u_broad_grid;
  for (int i = 0; i < u_broad_grid; ++i) {
    float cos_t = sg_grid_polar_cosine(lambda, u_broad_grid, i);
    for (int j = 0; j < cells_per_row; ++j) {
      vec3 wi = sg_grid_direction(axis, cos_t, u_broad_grid, j);
      if (dot(wi, n) <= 0.0) continue;  // below the surface: the model is zero there
      int c = i * cells_per_row + j;
      uint word = broad_word(vertex, slot * u_broad_words_per_sg + c / 32);
      if (((word >> uint(c - (c / 32) * 32)) & 1u) == 0u) continue;
      lobe += cloth_integrand_split_view(view, wi, 0.0);
    }
  }
  return lobe * sg_grid_cell_weight(lambda, u_broad_grid);
}
