// Method `mizutani` (docs/design.md §4) in GLSL ES 3.0: the twin of
// render/methods/mizutani/mizutani.cpp, term by term (the comments there give the equations);
// tests/gpu/mizutani_parity_test.cpp pins the two together. Needs microcylinder.glsl and
// hemisphere_grid.glsl first (threads, tilts, fiber_angles; the table grids) and MAX_SGS defined.
#define MAX_W_TABLES 256
#define MAX_W_LEVELS 16
#define THETA_SEGMENTS 6

uniform int u_sg_count;
uniform vec3 u_sg_axis[MAX_SGS];
uniform float u_sg_lambda[MAX_SGS];
uniform vec3 u_sg_amplitude[MAX_SGS];

// Weighting tables (render/runtime/weighting_tables.h): U and V factors as R32F textures, texel
// (grid node, row); table d·levels + level owns rows [first, first + rank).
uniform highp sampler2D u_w_u, u_w_v;
uniform int u_w_xi_n, u_w_wo_n, u_w_levels;
uniform float u_w_log_lambda[MAX_W_LEVELS];
uniform int u_w_sample_table[2 * MAX_TANGENT_SAMPLES];
uniform ivec2 u_w_table[MAX_W_TABLES];  // (first row, rank)

// Azimuthal table T_m / Z (render/runtime/azimuthal_table.h) as RGBA32F, texel
// (φ_o node, φ_k node, group·L + λ' node) holding powers 4·group .. 4·group + 3.
uniform highp sampler3D u_azimuthal;
uniform ivec3 u_az_nodes;  // φ_o, φ_k, λ' node counts
uniform float u_az_lambda_max;

// erf: Taylor series near 0 (relative accuracy where values are small), Abramowitz–Stegun
// 7.1.26 beyond (absolute error 1.5e-7). GLSL ES has no erf.
float erf_approx(float x) {
  float a = abs(x);
  if (a < 0.5) {
    float x2 = x * x;
    return 1.1283791671 * x * (1.0 - x2 * (1.0 / 3.0 - x2 * (0.1 - x2 * (1.0 / 42.0 - x2 / 216.0))));
  }
  float t = 1.0 / (1.0 + 0.3275911 * a);
  float y = 1.0 - ((((1.061405429 * t - 1.453152027) * t + 1.421413741) * t - 0.284496736) * t + 0.254829592) * t *
                      exp(-a * a);
  return sign(x) * y;
}

// Z(λ') = 2π e^{−λ'} I_0(λ'): Abramowitz–Stegun 9.8.1 / 9.8.2 (relative error < 2e-7).
float circular_gaussian_full_integral(float x) {
  if (x < 3.75) {
    float t = (x / 3.75) * (x / 3.75);
    float i0 = 1.0 + t * (3.5156229 + t * (3.0899424 + t * (1.2067492 + t * (0.2659732 + t * (0.0360768 + t * 0.0045813)))));
    return 2.0 * PI * exp(-x) * i0;
  }
  float t = 3.75 / x;
  float p = 0.39894228 + t * (0.01328592 + t * (0.00225319 + t * (-0.00157565 + t * (0.00916281 +
            t * (-0.02057706 + t * (0.02635537 + t * (-0.01647633 + t * 0.00392377)))))));
  return 2.0 * PI * p / sqrt(x);
}

// Position of x on a node axis [lo, hi] with n nodes: cell index and fraction (AzimuthalTable).
void locate(float x, float lo, float hi, int n, out int i, out float f) {
  float s = clamp((x - lo) / (hi - lo), 0.0, 1.0) * float(n - 1);
  i = clamp(int(floor(s)), 0, n - 2);
  f = s - float(i);
}

// T_m(φ_o, φ_k, λ') for m = 0..11 (the 12th unused): AzimuthalTable::value.
void azimuthal_values(float phi_o, float phi_k, float lp, out vec4 t0, out vec4 t1, out vec4 t2) {
  phi_k = phi_k - 2.0 * PI * floor(phi_k / (2.0 * PI) + 0.5);
  float z = circular_gaussian_full_integral(lp);
  lp = min(lp, u_az_lambda_max);
  int io, ik, il;
  float fo, fk, fl;
  locate(phi_o, -0.5 * PI, 0.5 * PI, u_az_nodes.x, io, fo);
  locate(phi_k, -PI, PI, u_az_nodes.y, ik, fk);
  locate(log(1.0 + lp) / log(1.0 + u_az_lambda_max), 0.0, 1.0, u_az_nodes.z, il, fl);
  t0 = vec4(0.0), t1 = vec4(0.0), t2 = vec4(0.0);
  for (int dl = 0; dl < 2; ++dl)
    for (int dk = 0; dk < 2; ++dk)
      for (int d0 = 0; d0 < 2; ++d0) {
        float w = (dl == 1 ? fl : 1.0 - fl) * (dk == 1 ? fk : 1.0 - fk) * (d0 == 1 ? fo : 1.0 - fo);
        ivec3 c = ivec3(io + d0, ik + dk, il + dl);
        t0 += w * texelFetch(u_azimuthal, c, 0);
        t1 += w * texelFetch(u_azimuthal, c + ivec3(0, 0, u_az_nodes.z), 0);
        t2 += w * texelFetch(u_azimuthal, c + ivec3(0, 0, 2 * u_az_nodes.z), 0);
      }
  t0 *= z, t1 *= z, t2 *= z;
}

// Bilinear taps on an n×n node grid: first index (the others are +1, +n, +n+1) and fractions.
void grid_tap(vec3 w, int n, out int k, out vec2 f) {
  vec2 s = (node_square_from_hemisphere(normalize(w)) + 1.0) * 0.5 * float(n - 1);
  ivec2 i0 = clamp(ivec2(floor(s)), ivec2(0), ivec2(n - 2));
  f = clamp(s - vec2(i0), 0.0, 1.0);
  k = i0.y * n + i0.x;
}

float factor_at(highp sampler2D tex, int k, int n, vec2 f, int row) {
  return (1.0 - f.x) * (1.0 - f.y) * texelFetch(tex, ivec2(k, row), 0).r +
         f.x * (1.0 - f.y) * texelFetch(tex, ivec2(k + 1, row), 0).r +
         (1.0 - f.x) * f.y * texelFetch(tex, ivec2(k + n, row), 0).r +
         f.x * f.y * texelFetch(tex, ivec2(k + n + 1, row), 0).r;
}

// T_{t,λ}(ξ, ω_o): WeightingTables::value.
float weighting_value(int s, float lambda, vec3 xi, vec3 wo) {
  int levels = u_w_levels;
  float ll = clamp(log(lambda), u_w_log_lambda[0], u_w_log_lambda[levels - 1]);
  int l0 = 0, l1 = 0;
  float f = 0.0;
  if (levels > 1) {
    while (l0 + 2 < levels && u_w_log_lambda[l0 + 1] < ll) ++l0;
    l1 = l0 + 1;
    f = clamp((ll - u_w_log_lambda[l0]) / (u_w_log_lambda[l1] - u_w_log_lambda[l0]), 0.0, 1.0);
  }
  int ka, kb;
  vec2 fa, fb;
  grid_tap(xi, u_w_xi_n, ka, fa);
  grid_tap(wo, u_w_wo_n, kb, fb);
  int d = u_w_sample_table[s];
  float total = 0.0;
  for (int k = 0; k < 2; ++k) {
    float wl = k == 0 ? 1.0 - f : f;
    if (wl == 0.0) continue;
    ivec2 tb = u_w_table[d * levels + (k == 0 ? l0 : l1)];
    float sum = 0.0;
    for (int r = 0; r < tb.y; ++r)
      sum += factor_at(u_w_u, ka, u_w_xi_n, fa, tb.x + r) * factor_at(u_w_v, kb, u_w_wo_n, fb, tb.x + r);
    total += wl * sum;
  }
  return total;
}

// α·g^c product of two circular Gaussians (alpha, mu, sigma): seed 001 Eq. 17.
vec3 circular_product(vec3 a, vec3 b) {
  float k1 = 2.0 / (a.z * a.z), k2 = 2.0 / (b.z * b.z);
  float c = k1 * cos(a.y) + k2 * cos(b.y), s = k1 * sin(a.y) + k2 * sin(b.y);
  float k3 = length(vec2(c, s));
  float half_d = sin(0.5 * (a.y - b.y));
  float denom = k3 + k1 + k2;
  float alpha = a.x * b.x * (denom > 0.0 ? exp(-4.0 * k1 * k2 * half_d * half_d / denom) : 1.0);
  return k3 > 0.0 ? vec3(alpha, atan(s, c), sqrt(2.0 / k3)) : vec3(alpha, a.y, 1e30);
}

// Σ over the segments of ∫ g(θ;μ,σ)·h(θ) dθ, h linear between its node values.
float piecewise_linear_integral(float h[THETA_SEGMENTS + 1], float mu, float sigma) {
  const float seg_width = PI / float(THETA_SEGMENTS);
  float sum = 0.0;
  for (int s = 0; s < THETA_SEGMENTS; ++s) {
    float a = -0.5 * PI + float(s) * seg_width, b = a + seg_width;
    float m0, m1;
    if (!(sigma < 1e4)) {
      m0 = seg_width, m1 = 0.5 * seg_width * seg_width;
    } else {
      float za = (a - mu) / sigma, zb = (b - mu) / sigma;
      m0 = 0.5 * sqrt(PI) * sigma * (erf_approx(zb) - erf_approx(za));
      m1 = (mu - a) * m0 + 0.5 * sigma * sigma * (exp(-za * za) - exp(-zb * zb));
    }
    sum += h[s] * m0 + (h[s + 1] - h[s]) / seg_width * m1;
  }
  return sum;
}

// L_o at a frame (n, u, v = n × u) toward wo under the u_sg_* lights: mizutani_radiance().
vec3 mizutani_radiance(vec3 n, vec3 u, vec3 wo) {
  if (dot(wo, n) <= 0.0) return vec3(0.0);
  vec3 v = cross(n, u);
  vec3 wo_local = vec3(dot(wo, u), dot(wo, v), dot(wo, n));
  vec3 total = vec3(0.0);
  for (int g = 0; g < u_sg_count; ++g) {
    vec3 xi = u_sg_axis[g];
    float lambda = u_sg_lambda[g];
    vec3 xi_local = vec3(dot(xi, u), dot(xi, v), dot(xi, n));
    float sigma_k = sqrt(2.0 / lambda);
    for (int j = 0; j < 2; ++j) {
      Thread p = u_threads[j];
      vec3 along = j == 0 ? u : v, axis = j == 0 ? v : u;
      float f0 = ((p.eta - 1.0) / (p.eta + 1.0)) * ((p.eta - 1.0) / (p.eta + 1.0));
      float gs = sqrt(2.0) * p.gamma_s, gv = sqrt(2.0) * p.gamma_v;
      vec3 sum = vec3(0.0);
      for (int k = 0; k < p.samples; ++k) {
        int s = j == 0 ? k : u_threads[0].samples + k;
        float T = weighting_value(s, lambda, xi_local, wo_local);
        if (T <= 0.0) continue;
        float alpha = thread_tilt(j * MAX_TANGENT_SAMPLES + k);
        FiberAngles o = fiber_angles(along, axis, n, alpha, wo);
        FiberAngles kf = fiber_angles(along, axis, n, alpha, xi);
        float cos_k = cos(kf.theta);
        float h_surf[THETA_SEGMENTS + 1], h_vol[THETA_SEGMENTS + 1];
        h_surf[0] = h_vol[0] = h_surf[THETA_SEGMENTS] = h_vol[THETA_SEGMENTS] = 0.0;  // cos²θ_i = 0 there
        for (int i = 1; i < THETA_SEGMENTS; ++i) {
          float theta = -0.5 * PI + float(i) * PI / float(THETA_SEGMENTS);
          float cos_t = max(cos(theta), 0.0);
          float cos_d = cos(0.5 * (theta - o.theta));
          // Schlick in x = cos(φ_d/2): F_r = Σ cs_l x^l, (1 − F_r)² = Σ cv_m x^m.
          float cs[6], tr[6], cv[11];
          float pw = 1.0;
          const float binom5[6] = float[6](1.0, 5.0, 10.0, 10.0, 5.0, 1.0);
          for (int l = 0; l < 6; ++l, pw *= -cos_d) {
            cs[l] = (1.0 - f0) * binom5[l] * pw;
            tr[l] = l == 0 ? 0.0 : -cs[l];
          }
          cs[0] += f0;
          for (int m = 0; m < 11; ++m) cv[m] = 0.0;
          for (int a = 1; a < 6; ++a)
            for (int b = 1; b < 6; ++b) cv[a + b] += tr[a] * tr[b];
          vec4 t0, t1, t2;
          azimuthal_values(o.phi, kf.phi, lambda * cos_t * cos_k, t0, t1, t2);
          float tm[11] = float[11](t0.x, t0.y, t0.z, t0.w, t1.x, t1.y, t1.z, t1.w, t2.x, t2.y, t2.z);
          float sum_s = 0.0, sum_v = 0.0;
          for (int m = 0; m < 11; ++m) {
            if (m >= 1 && m <= 6) sum_s += cs[m - 1] * tm[m];
            sum_v += cv[m] * tm[m];
          }
          float geo = cos_t * cos_t / max(cos_d * cos_d, DENOMINATOR_FLOOR);
          h_surf[i] = geo * sum_s;
          h_vol[i] = geo * sum_v / max(cos_t + cos(o.theta), DENOMINATOR_FLOOR);
        }
        vec3 light = vec3(1.0, kf.theta, sigma_k);
        vec3 ls = circular_product(light, vec3(1.0 / (sqrt(PI) * gs), -o.theta, 2.0 * gs));
        vec3 lv = circular_product(light, vec3(1.0 / (sqrt(PI) * gv), -o.theta, 2.0 * gv));
        float i_surf = ls.x * piecewise_linear_integral(h_surf, ls.y, ls.z);
        float i_vol = (1.0 - p.kd) * lv.x * piecewise_linear_integral(h_vol, lv.y, lv.z) +
                      p.kd * piecewise_linear_integral(h_vol, kf.theta, sigma_k);
        sum += T * (vec3(max(i_surf, 0.0)) + max(i_vol, 0.0) * p.albedo);
      }
      total += u_sg_amplitude[g] * sum / float(p.samples);
    }
  }
  return total;
}
