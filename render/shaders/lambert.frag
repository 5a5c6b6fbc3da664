// Lambertian floor/occluder: radiance = albedo/π · E, with E the SG irradiance the CPU put in
// the vertex colour slot (render/core's sg_clamped_cosine_integral, once per light change).
in vec3 v_position;
in vec3 v_normal;
in vec3 v_warp;
in vec3 v_colour;
uniform vec3 u_albedo;
out vec4 o_radiance;
const float PI = 3.14159265358979;
void main() { o_radiance = vec4(u_albedo / PI * v_colour, 1.0); }
