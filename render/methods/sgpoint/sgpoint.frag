// Method `sgpoint` (docs/design.md §4): each SG as a directional light along its axis carrying the
// SG's whole power P_k = μ_k·2π(1−e^{−2λ})/λ, shading with the full model. The naive baseline.
in vec3 v_position;
in vec3 v_normal;
in vec3 v_warp;
in vec3 v_colour;
#define MAX_SGS 40
uniform int u_sg_count;
uniform vec3 u_sg_axis[MAX_SGS];
uniform vec3 u_sg_power[MAX_SGS];
uniform vec3 u_eye;
out vec4 o_radiance;
void main() {
  vec3 n = normalize(v_normal);
  vec3 wo = normalize(u_eye - v_position);
  if (dot(n, wo) < 0.0) n = -n;  // thin cloth seen from behind: shade the side facing the eye
  vec3 u = normalize(v_warp - dot(v_warp, n) * n);
  vec3 l = vec3(0.0);
  for (int k = 0; k < u_sg_count; ++k) l += u_sg_power[k] * cloth_integrand(n, u, u_sg_axis[k], wo);
  o_radiance = vec4(l, 1.0);
}
