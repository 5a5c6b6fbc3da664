// Seed 000 §3, Eq. 8–14, as one function, iwasaki_radiance(): for each SG k and tangent sample t,
//   T_{t,λ_k}(ξ_k, ω_o) from the SVD factors (two λ levels, bilinear in both direction grids),
//   and for the longitudinal lobes T at the surface lobe's peak (fiber_direction)
//   × the circular-Gaussian product of the SG with each longitudinal lobe (Eq. 11, 13)
//   × the smooth factors at the product's peak × the visibility ratio H (Eq. 12, 14: sigmoid
//   with the baked gain κ, d and ∇d at the SG axis per vertex, computed when the lighting changes),
//   and the surface's horizon as a second linear boundary (closed-form H, the smaller one wins).
// The same steps as render/methods/iwasaki/iwasaki.cpp (+ iwasaki_visibility.cpp); the parity test pins
// them. Needs microcylinder.glsl (threads, tilts, fiber_angles, fresnel_dielectric), erf.glsl,
// sg_lighting.glsl (the SG integrals), hemisphere_grid.glsl and facet_horizon.glsl before it.
// Method `iwasaki` calls it per pixel (iwasaki.frag), `iwasaki_vertex` per vertex and SG
// (iwasaki_vertex_pass.frag, a fragment pass with one texel per vertex and SG; iwasaki_vertex.vert
// and .frag interpolate each SG's result and cut it by the facet's plane).
#define MAX_TABLES 512
#define MAX_LEVELS 32
const float HALF_PI = 1.57079632679490;

uniform vec3 u_eye;
// u_sg_count, u_sg_axis, u_sg_amplitude: sg_lighting.glsl's.
uniform float u_sg_sigma[MAX_SGS];    // σ_k = √(2/λ_k)
uniform ivec2 u_sg_levels[MAX_SGS];   // the two λ levels of T (WeightingTables::level_weights)
uniform float u_sg_level_w[MAX_SGS];  // weight of the second

uniform highp sampler2DArray u_t_u;   // U factors: ξ node grid, 4 ranks per layer
uniform highp sampler2DArray u_t_v;   // V factors: ω_o node grid
// The tables below are packed four scalars (two pairs) to a vector, as u_tilts is
// (microcylinder.glsl): a program must fit in NVIDIA's 1024 uniform registers.
uniform ivec4 u_tables[MAX_TABLES / 2];   // (first layer, layers) of table d·levels + l, two a vector
uniform int u_levels;
uniform vec4 u_log_lambdas[MAX_LEVELS / 4];  // log λ of each level (WeightingTables::lambdas)
uniform ivec4 u_sample_table[MAX_TANGENT_SAMPLES / 2];  // sample s (thread 0's, then thread 1's) → d
uniform float u_xi_n;
uniform vec4 u_tilt_spreads[MAX_TANGENT_SAMPLES / 2];  // ClothBsdf::tilt_spread, laid out as u_tilts
// ClothBsdf::sample_multiplicity, laid out as u_tilts: a sample stands for this many of its
// thread's samples (those with its tilt and spread), 0 where an earlier one stands for it.
uniform vec4 u_sample_multiplicity[MAX_TANGENT_SAMPLES / 2];
ivec2 table_entry(int index) {
  ivec4 pair = u_tables[index >> 1];
  return (index & 1) == 0 ? pair.xy : pair.zw;
}
float log_lambda(int level) { return u_log_lambdas[level >> 2][level & 3]; }
int sample_table(int s) { return u_sample_table[s >> 2][s & 3]; }
float tilt_spread(int s) { return u_tilt_spreads[s >> 2][s & 3]; }
float sample_multiplicity(int s) { return u_sample_multiplicity[s >> 2][s & 3]; }
uniform float u_wo_n;

uniform bool u_visibility;
uniform highp sampler2D u_sg_visibility;  // (d, ∂d/∂θ', ∂d/∂φ') per (vertex, SG): SgVisibilityTexture
uniform int u_sg_visibility_per_row;      // vertices per texel row
// The texture holds (V_k, 0, 0) from a visibility mask instead (SgVisibility::from_mask): the SG's
// amplitude times V_k, the lobes cut at the surface's horizon alone (iwasaki.cpp's open_share).
uniform bool u_visibility_open_share;
uniform highp sampler3D u_kappa;      // κ·s over (β, σ', σ_l) as x, y, z
uniform vec3 u_kappa_n;               // nodes along σ_l, σ', β
uniform vec2 u_kappa_sigma;           // σ range (min, max)

// Node grid of n nodes: node i at texel centre (i + ½)/n, s = −1 + 2i/(n−1).
vec2 node_texcoord(vec2 s, float n) { return s * (0.5 * (n - 1.0) / n) + 0.5; }

// Σ_r U_r(ξ)·V_r(ω_o) of table `index`.
float table_dot(int index, vec2 xi_tc, vec2 wo_tc) {
  ivec2 e = table_entry(index);
  float sum = 0.0;
  for (int l = 0; l < e.y; ++l) {
    float layer = float(e.x + l);
    sum += dot(texture(u_t_u, vec3(xi_tc, layer)), texture(u_t_v, vec3(wo_tc, layer)));
  }
  return sum;
}

// T of distinct table d at levels l0, l1 (weight lw of the second).
float table_t(int d, int l0, int l1, float lw, vec2 xi_tc, vec2 wo_tc) {
  float T = 0.0;
  if (lw < 1.0) T += (1.0 - lw) * table_dot(d * u_levels + l0, xi_tc, wo_tc);
  if (lw > 0.0) T += lw * table_dot(d * u_levels + l1, xi_tc, wo_tc);
  return T;
}

// --- core/circular_gaussian.cpp
struct Lobe { float alpha; float mu; float sigma; };
Lobe lobe_product(Lobe a, Lobe b) {
  float k1 = 2.0 / (a.sigma * a.sigma), k2 = 2.0 / (b.sigma * b.sigma);
  float c = k1 * cos(a.mu) + k2 * cos(b.mu);
  float s = k1 * sin(a.mu) + k2 * sin(b.mu);
  float k3 = length(vec2(c, s));
  float h = sin(0.5 * (a.mu - b.mu));
  float denom = k3 + k1 + k2;
  return Lobe(a.alpha * b.alpha * (denom > 0.0 ? exp(-4.0 * k1 * k2 * h * h / denom) : 1.0),
              k3 > 0.0 ? atan(s, c) : a.mu, sqrt(2.0 / k3));
}
// iwasaki.cpp's lobe_sigma_prime: cos θ·cos θ_k kept ≥ 1e−6 (σ' = ∞ would make ∞·0 = NaN).
float sigma_prime(float sigma_k, float theta, float theta_k) { return sigma_k / sqrt(max(cos(theta) * cos(theta_k), 1e-6)); }
// core's circular_gaussian_circle_integral: ∫ over the whole circle, 2π e^{−κ}I₀(κ) (A&S 9.8.1–2).
float circle_integral(float sigma) {
  float k = 2.0 / (sigma * sigma);
  float scaled;
  if (k < 3.75) {
    float t = (k / 3.75) * (k / 3.75);
    scaled = exp(-k) * (1.0 + t * (3.5156229 + t * (3.0899424 + t * (1.2067492 + t * (0.2659732 + t * (0.0360768 + t * 0.0045813))))));
  } else {
    float t = 3.75 / k;
    scaled = (0.39894228 + t * (0.01328592 + t * (0.00225319 + t * (-0.00157565 + t * (0.00916281 +
             t * (-0.02057706 + t * (0.02635537 + t * (-0.01647633 + t * 0.00392377)))))))) / sqrt(k);
  }
  return 2.0 * PI * scaled;
}
// iwasaki.cpp's pair_integral: θ over [−π/2, π/2] (Gaussian), φ over the whole circle.
float pair_integral(float theta_l, float sigma_l, float sp) {
  float a = erf_nr((HALF_PI - theta_l) / sigma_l) - erf_nr((-HALF_PI - theta_l) / sigma_l);
  return 0.5 * sqrt(PI) * sigma_l * a * circle_integral(sp);
}
// iwasaki.cpp's separable_spread and lobe_spread.
float separable_spread(float lambda, float theta_k, float sigma_k) {
  float frozen = 0.5 * sqrt(PI) * sigma_k * (erf_nr((HALF_PI - theta_k) / sigma_k) - erf_nr((-HALF_PI - theta_k) / sigma_k)) *
                 circle_integral(sigma_prime(sigma_k, theta_k, theta_k)) * max(cos(theta_k), 1e-3);
  return clamp(4.0 * PI * sg_one_minus_exp_over(2.0 * lambda) / frozen, 0.25, 1.0);
}
float lobe_spread(float spread_k, float sigma_l, float sigma_k) { return pow(spread_k, (sigma_l * sigma_l) / (sigma_k * sigma_k)); }

// --- methods/iwasaki_visibility.cpp: (d, ∂d/∂θ', ∂d/∂φ') of SG k blended over the corners
// (step 2), then ∇d carried to a sample frame's (θ, φ) (step 3).
vec3 sg_visibility(int vertex, int k) {
  int p = u_sg_visibility_per_row;
  return texelFetch(u_sg_visibility, ivec2((vertex - (vertex / p) * p) * u_sg_count + k, vertex / p), 0).rgb;
}
vec3 sdf_in_sample_frame(vec3 n, vec3 u, vec3 v, vec3 t, vec3 np, vec3 b, float theta, float phi, vec3 s) {
  FiberDirection d = fiber_direction(t, np, b, theta, phi);
  vec3 w = d.w, dw_dtheta = d.dw_dtheta, dw_dphi = d.dw_dphi;
  float wn = dot(w, n), wv = dot(w, v);
  float cos2 = max(wn * wn + wv * wv, 1e-8);
  vec3 dtheta_v = u / sqrt(cos2);
  vec3 dphi_v = (wn * v - wv * n) / cos2;
  return vec3(s.x, s.y * dot(dtheta_v, dw_dtheta) + s.z * dot(dphi_v, dw_dtheta),
              s.y * dot(dtheta_v, dw_dphi) + s.z * dot(dphi_v, dw_dphi));
}
// --- bake/visibility/sigmoid_gain.cpp's SigmoidGainTable::h.
float visibility_h(float sigma_l, float sp, vec3 s) {
  float len = length(s.yz);
  if (len == 0.0) return s.x > 0.0 ? 1.0 : (s.x < 0.0 ? 0.0 : 0.5);
  float spread = sqrt(0.5 * (sigma_l * sigma_l * s.y * s.y + sp * sp * s.z * s.z) / (len * len));
  float range = log(u_kappa_sigma.y / u_kappa_sigma.x);
  float ul = clamp(log(clamp(sigma_l, u_kappa_sigma.x, u_kappa_sigma.y) / u_kappa_sigma.x) / range * (u_kappa_n.x - 1.0), 0.0, u_kappa_n.x - 1.0);
  float up = clamp(log(clamp(sp, u_kappa_sigma.x, u_kappa_sigma.y) / u_kappa_sigma.x) / range * (u_kappa_n.y - 1.0), 0.0, u_kappa_n.y - 1.0);
  float ub = clamp(atan(abs(s.z), abs(s.y)) / HALF_PI * (u_kappa_n.z - 1.0), 0.0, u_kappa_n.z - 1.0);
  float g = texture(u_kappa, (vec3(ub, up, ul) + 0.5) / u_kappa_n.zyx).r;
  return 1.0 / (1.0 + exp(-(g / spread) * s.x / len));
}

// --- iwasaki.cpp's horizon_ratio: the surface's horizon as a linear visibility boundary at the
// lobe's peak; hz = (t·n, n'·n, b·n) of the sample frame.
float horizon_h(float theta, float phi, float sigma_l, float sp, vec3 hz) {
  float ct = cos(theta), st = sin(theta), cp = cos(phi), sn = sin(phi);
  float radial = cp * hz.y + sn * hz.z;
  float h = st * hz.x + ct * radial;
  float spread = length(vec2((ct * hz.x - st * radial) * sigma_l, ct * (cp * hz.z - sn * hz.y) * sp));
  if (spread == 0.0) return h > 0.0 ? 1.0 : (h < 0.0 ? 0.0 : 0.5);
  return 0.5 * erfc_nr(-h / spread);
}

// --- iwasaki.cpp's lobe_horizon_fraction: the SG share above the surface (core's
// sg_hemisphere_fraction, facet_horizon.glsl) for the lobe's width along h's gradient.
float horizon_fraction(float theta, float phi, float sigma_l, float sp, vec3 hz) {
  float ct = cos(theta), st = sin(theta), cp = cos(phi), sn = sin(phi);
  float radial = cp * hz.y + sn * hz.z;
  float h = st * hz.x + ct * radial;
  float h_dtheta = ct * hz.x - st * radial, h_dphi = ct * (cp * hz.z - sn * hz.y);
  float width_phi = sp * ct;
  float g_theta = h_dtheta * h_dtheta, g_phi = ct > 1e-6 ? h_dphi * h_dphi / (ct * ct) : 0.0;
  float grad = g_theta + g_phi;
  float width2 = grad > 1e-6 ? (g_theta * sigma_l * sigma_l + g_phi * width_phi * width_phi) / grad
                             : 0.5 * (sigma_l * sigma_l + width_phi * width_phi);
  return sg_hemisphere_fraction(2.0 / width2, h);
}

// ∫∫ g^c g^c V' of one lobe (Eq. 12–13); `sdf` = (d, ∂d/∂θ, ∂d/∂φ) looked up once per (SG,
// sample) at (θ_k, φ_k) and carried to the lobe's peak along its plane (iwasaki.cpp, LinearSdf);
// V' is the horizon's alone, or the smaller of the horizon's and the SDF's (iwasaki.cpp).
// The bake cast the visibility from the side the mesh normal points to; cloth seen from behind
// (a fold's top layer, a curtain's back) is shaded on its other side, for which it holds nothing:
// taken open there (iwasaki.h's on_side_shaded). A caller that turns the normal to the eye itself
// (cloth_pixel_frame) sets iwasaki_behind where the mesh normal faced away.
bool iwasaki_behind = false;
// `sdf_shadows`: the lobe is cut by the baked SDF (sdf) as well as by the horizon.
float lobe_integral(float theta_l, float sigma_l, float phi_k, float sp, vec3 sdf, float theta_k, vec3 hz, bool sdf_shadows) {
  float i = pair_integral(theta_l, sigma_l, sp);
  float h = horizon_fraction(theta_l, phi_k, sigma_l, sp, hz);
  if (!sdf_shadows) return i * h;
  return i * min(h, visibility_h(sigma_l, sp, vec3(sdf.x + sdf.y * (theta_l - theta_k), sdf.yz)));
}

// --- core's horizon_sliver_weight and horizon_sharpness_for_mean_cosine (above_horizon's rule for
// sharp lobes: the sliver's power and mean cosine above the horizon).
// a^(1−w)·b^w as C++'s std::pow gives it: pow(0, 0) is undefined in GLSL (NVIDIA: exp2(0·log2 0) =
// NaN), and a sharp lobe far below the horizon has a = 0 with w = 1.
float geometric_blend(float a, float b, float w) {
  if (w >= 1.0) return b;
  if (w <= 0.0) return a;
  return pow(a, 1.0 - w) * pow(b, w);
}
float horizon_sliver_weight(float lambda) { return clamp(log(lambda / 4.0) / log(4.0), 0.0, 1.0); }
float horizon_mean_cosine(float log_lambda) {
  float l = exp(log_lambda);
  return sg_clamped_cosine_integral(l, 0.0) / sg_hemisphere_integral(l, 0.0);
}
float horizon_sharpness_for_mean_cosine(float mean_cosine, float min_lambda) {
  float lo = log(min_lambda), hi = lo + 12.0;
  if (horizon_mean_cosine(lo) <= mean_cosine) return min_lambda;
  for (int i = 0; i < 16; ++i) {
    float mid = 0.5 * (lo + hi);
    if (horizon_mean_cosine(mid) > mean_cosine) lo = mid; else hi = mid;
  }
  return exp(0.5 * (lo + hi));
}

// The facet's plane (facet_horizon.glsl) cuts each SG too. A per-pixel caller sets
// iwasaki_facet_normal (facing the eye) before iwasaki_radiance; zero (per vertex): none.
vec3 iwasaki_facet_normal = vec3(0.0);
void set_facet_normal(vec3 position) { iwasaki_facet_normal = facet_normal(position, u_eye); }

// What multiplies each thread's albedo A_j at the point shaded: its texel where the cloth is textured
// (thread_maps.glsl), else 1. A per-pixel caller sets it before iwasaki_radiance.
vec3 iwasaki_thread_tint[2] = vec3[2](vec3(1.0), vec3(1.0));

// SG k's light at a cloth point at unit amplitude (μ_k = 1), split into (surface part, thread 0's
// volume part per unit albedo, thread 1's): the radiance is μ_k·(x + A_0·y + A_1·z), every factor
// of the SG's (its share above the horizon, the facet's cut, the visible share) a scalar in x, y, z.
// `corners` are the vertices whose SDF grids are blended with weights `bary` (the triangle's three
// at a pixel; one vertex, weight 1, per vertex). Zero for a broad SG (broad_lobe_quadrature.glsl).
vec3 iwasaki_sg_split(vec3 position, vec3 normal, vec3 warp, ivec3 corners, vec3 bary, int k) {
  vec3 n = normalize(normal);
  vec3 wo = normalize(u_eye - position);
  bool behind = iwasaki_behind;
  if (dot(n, wo) < 0.0) {  // thin cloth seen from behind: shade the side facing the eye
    n = -n;
    behind = true;
  }
  bool baked_side = u_visibility && !behind;
  bool sdf_shadows = baked_side && !u_visibility_open_share;
  vec3 u = normalize(warp - dot(warp, n) * n);
  vec3 v = cross(n, u);
  vec3 wo_local = vec3(dot(wo, u), dot(wo, v), dot(wo, n));
  vec3 split = vec3(0.0);
  if (wo_local.z > 0.0 && u_sg_broad[k] == 0) {
    vec2 wo_tc = node_texcoord(node_square_from_hemisphere(normalize(wo_local)), u_wo_n);
    {
      vec3 xi = u_sg_axis[k];
      float sigma_k = u_sg_sigma[k];
      float amplitude = facet_horizon_factor(u_sg_sharpness[k], xi, n, iwasaki_facet_normal);
      int l0 = u_sg_levels[k].x, l1 = u_sg_levels[k].y;
      float lw = u_sg_level_w[k];
      // core's above_horizon: a lobe whose axis is below the surface as its part above it.
      float c = dot(xi, n);
      if (c < 0.0) {
        float lambda = 2.0 / (sigma_k * sigma_k);
        vec3 e = xi - c * n;
        float s = length(e);
        e = s > 1e-6 ? e / s : normalize(cross(n, abs(n.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0)));
        float lp = max(lambda * s, exp(log_lambda(0)));
        float scale = sg_clamped_cosine_integral(lambda, c) / sg_clamped_cosine_integral(lp, 0.0);
        float w = horizon_sliver_weight(lambda);
        if (w > 0.0) {
          float power = sg_hemisphere_integral(lambda, c);
          float ls = horizon_sharpness_for_mean_cosine(sg_clamped_cosine_integral(lambda, c) / power, lp);
          scale = geometric_blend(scale, power / sg_hemisphere_integral(ls, 0.0), w);
          lp = geometric_blend(lp, ls, w);
        }
        amplitude *= scale;
        xi = e;
        sigma_k = sqrt(2.0 / lp);
        // WeightingTables::level_weights for λ'.
        float ll = clamp(log(lp), log_lambda(0), log_lambda(u_levels - 1));
        l0 = 0;
        while (l0 + 2 < u_levels && log_lambda(l0 + 1) < ll) ++l0;
        l1 = min(l0 + 1, u_levels - 1);
        lw = l1 > l0 ? clamp((ll - log_lambda(l0)) / (log_lambda(l1) - log_lambda(l0)), 0.0, 1.0) : 0.0;
      }
      float lambda_k = 2.0 / (sigma_k * sigma_k);
      float w_peak = clamp(0.5 * log2(lambda_k / 2.0), 0.0, 1.0);  // iwasaki.cpp's lobe_peak_weight
      vec2 xi_tc = node_texcoord(node_square_from_hemisphere(vec3(dot(xi, u), dot(xi, v), dot(xi, n))), u_xi_n);
      vec3 vis_k = vec3(0.0);
      if (baked_side) {
        vis_k = bary.x * sg_visibility(corners.x, k);
        // Per vertex the weights are (1, 0, 0): the other corners cost two fetches for nothing.
        if (bary.y != 0.0 || bary.z != 0.0)
          vis_k += bary.y * sg_visibility(corners.y, k) + bary.z * sg_visibility(corners.z, k);
        if (u_visibility_open_share) amplitude *= vis_k.x;
      }
      for (int j = 0; j < 2; ++j) {
        Thread p = u_threads[j];
        int count = p.samples;
        vec3 along = j == 0 ? u : v, axis = j == 0 ? v : u;
        float surf = 0.0, vol = 0.0;
        for (int q = 0; q < count; ++q) {
          // Samples alike in tilt and spread give the same terms: the first, times their count.
          float m = sample_multiplicity(j * MAX_TANGENT_SAMPLES + q);
          if (m == 0.0) continue;
          int d = sample_table(j * MAX_TANGENT_SAMPLES + q);
          float T = max(table_t(d, l0, l1, lw, xi_tc, wo_tc), 0.0);
          float alpha = thread_tilt(j * MAX_TANGENT_SAMPLES + q);
          SampleFrame frame = sample_frame(along, n, alpha);
          vec3 t = frame.t, np = frame.np;
          FiberAngles fk = fiber_angles_in(t, np, axis, xi);
          FiberAngles fo = fiber_angles_in(t, np, axis, wo);
          float theta_k = fk.theta, phi_k = fk.phi;
          Lobe light = Lobe(1.0, theta_k, sigma_k);
          float spread_k = separable_spread(lambda_k, theta_k, sigma_k);
          vec3 hz = vec3(dot(t, n), dot(np, n), dot(axis, n));
          vec3 sdf = sdf_shadows ? sdf_in_sample_frame(n, u, v, t, np, axis, theta_k, phi_k, vis_k) : vec3(0.0);
          float phi_d = wrap_angle(phi_k - fo.phi);
          float cos_half = cos(0.5 * phi_d);
          // iwasaki.cpp's sample_lobe_width: each lobe widened by the tilts of the sample's arc; seed bandwidths.
          float c_tilt = 0.5 * (cos(phi_k) + cos(fo.phi)) * tilt_spread(j * MAX_TANGENT_SAMPLES + q);
          float gs = sqrt(2.0) * sqrt(p.gamma_s * p.gamma_s + c_tilt * c_tilt);
          float gv = sqrt(2.0) * sqrt(p.gamma_v * p.gamma_v + c_tilt * c_tilt);
          // T at the surface lobe's peak (fiber_direction) for both longitudinal lobes.
          Lobe ls = lobe_product(light, Lobe(1.0 / (sqrt(PI) * gs), -fo.theta, 2.0 * gs));
          float T_lobe = T;
          if (w_peak > 0.0) {
            vec3 peak = fiber_direction(t, np, axis, ls.mu, phi_k).w;
            vec2 peak_tc = node_texcoord(node_square_from_hemisphere(normalize(vec3(dot(peak, u), dot(peak, v), dot(peak, n)))), u_xi_n);
            T_lobe = mix(T, max(table_t(d, l0, l1, lw, peak_tc, wo_tc), 0.0), w_peak);
          }
          if (T <= 0.0 && T_lobe <= 0.0) continue;
          // Surface lobe.
          {
            Lobe l = ls;
            float sp = sigma_prime(sigma_k, l.mu, theta_k);
            float cos_d = cos(0.5 * (l.mu - fo.theta));
            float fr = fresnel_dielectric(p.eta, cos_d * cos_half);
            float geo = cos(l.mu) * cos(l.mu) / max(cos_d * cos_d, DENOMINATOR_FLOOR);
            surf += m * T_lobe * l.alpha * fr * cos_half * geo * lobe_integral(l.mu, l.sigma, phi_k, sp, sdf, theta_k, hz, sdf_shadows) *
                    lobe_spread(spread_k, l.sigma, sigma_k);
          }
          // Volume lobe and the isotropic k_d part.
          {
            Lobe l = lobe_product(light, Lobe(1.0 / (sqrt(PI) * gv), -fo.theta, 2.0 * gv));
            float cos_d = cos(0.5 * (l.mu - fo.theta));
            float tr = 1.0 - fresnel_dielectric(p.eta, cos_d * cos_half);
            float geo = cos(l.mu) * cos(l.mu) / max(cos_d * cos_d, DENOMINATOR_FLOOR);
            float sp = sigma_prime(sigma_k, l.mu, theta_k);
            float lobe = (1.0 - p.kd) * l.alpha * tr * tr * geo / max(cos(l.mu) + cos(fo.theta), DENOMINATOR_FLOOR) *
                         lobe_integral(l.mu, l.sigma, phi_k, sp, sdf, theta_k, hz, sdf_shadows) * lobe_spread(spread_k, l.sigma, sigma_k);
            float cos_dk = cos(0.5 * (theta_k - fo.theta));
            float tk = 1.0 - fresnel_dielectric(p.eta, cos_dk * cos_half);
            float geok = cos(theta_k) * cos(theta_k) / max(cos_dk * cos_dk, DENOMINATOR_FLOOR);
            float spk = sigma_prime(sigma_k, theta_k, theta_k);
            float iso = p.kd * tk * tk * geok / max(cos(theta_k) + cos(fo.theta), DENOMINATOR_FLOOR) *
                        lobe_integral(theta_k, sigma_k, phi_k, spk, sdf, theta_k, hz, sdf_shadows) * spread_k;
            vol += m * (T_lobe * lobe + T * iso);
          }
        }
        split.x += amplitude * surf / float(count);
        if (j == 0) split.y = amplitude * vol / float(count); else split.z = amplitude * vol / float(count);
      }
    }
  }
  return split;
}

// Outgoing radiance at a cloth point from SGs first … end − 1, each thread's albedo times its tint.
vec3 iwasaki_sg_radiance(vec3 position, vec3 normal, vec3 warp, ivec3 corners, vec3 bary, int first, int end) {
  vec3 a0 = u_threads[0].albedo * iwasaki_thread_tint[0], a1 = u_threads[1].albedo * iwasaki_thread_tint[1];
  vec3 sum = vec3(0.0);
  for (int k = first; k < min(end, u_sg_count); ++k) {
    vec3 s = iwasaki_sg_split(position, normal, warp, corners, bary, k);
    sum += u_sg_amplitude[k] * (vec3(s.x) + a0 * s.y + a1 * s.z);
  }
  return sum;
}
// From every SG.
vec3 iwasaki_radiance(vec3 position, vec3 normal, vec3 warp, ivec3 corners, vec3 bary) {
  return iwasaki_sg_radiance(position, normal, warp, corners, bary, 0, u_sg_count);
}
