// One face of the backdrop's cube map (gpu/backdrop_cube.h): the SG environment Σ_k G_k(d) in
// the direction d of each texel, faces in GL's order (+X, −X, +Y, −Y, +Z, −Z) with its (s, t)
// axes. Needs sg_lighting.glsl.
uniform int u_face;
uniform float u_face_size;
out vec4 o_radiance;
void main() {
  vec2 st = gl_FragCoord.xy / u_face_size * 2.0 - 1.0;
  float s = st.x, t = st.y;
  vec3 d = u_face == 0 ? vec3(1.0, -t, -s)
         : u_face == 1 ? vec3(-1.0, -t, s)
         : u_face == 2 ? vec3(s, 1.0, t)
         : u_face == 3 ? vec3(s, -1.0, -t)
         : u_face == 4 ? vec3(s, -t, 1.0)
                       : vec3(-s, -t, -1.0);
  d = normalize(d);
  vec3 l = vec3(0.0);
  for (int k = 0; k < u_sg_count; ++k) l += u_sg_amplitude[k] * exp(u_sg_sharpness[k] * (dot(d, u_sg_axis[k]) - 1.0));
  o_radiance = vec4(l, 1.0);
}
