// Method `iwasaki_vertex`: the per-vertex radiance, interpolated by the rasteriser.
in vec3 v_radiance;
out vec4 o_radiance;
void main() { o_radiance = vec4(v_radiance, 1.0); }
