// Method `sheer_vertex`: the per-vertex premultiplied source and alpha, interpolated.
in vec4 v_source;
out vec4 o_radiance;
void main() { o_radiance = v_source; }
