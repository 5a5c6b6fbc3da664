#pragma once
// The frame cost the setting search (bake/selection/scene_selection.h) ranks iwasaki's two shadings by,
// modelled at the kiosk's resolution (docs/design.md §6: speed at 640×480) so that per-pixel and
// per-vertex settings compete on one scale. Unit: one per-pixel shading step, one cloth pixel ×
// one SG × one tangent sample (the runtime's loops, methods/iwasaki/iwasaki.glsl).
//   per-pixel:   P × S × T̄
//   per-vertex:  kVertexStepCost × S × Σ_v T_v  +  kVertexDrawPixelCost × P
// P: cloth pixels of the frame at 640×480, S: SGs, T_v: tangent samples of vertex v's fabric
// (both threads), T̄: their mean over the cloth's vertices. The per-vertex pass runs the same
// shading over one texel per vertex (methods/vertex_pass/vertex_pass.h); the mesh's draw then
// interpolates it, a cost per cloth pixel independent of S and T.
//
// Calibrated on `weft bench` frame times at 640×480 (docs/bench/target_error/README.md, "Frame
// cost model"; kiosk_speed.csv), pillow / linen_plain (3+3 samples) / sky:elev=20, 10 SGs,
// grid-24 tables, llvmpipe on the shared 2-core VM (load 8–12), medians of 5 frames; 3764 cloth
// pixels at 160×120, so P ≈ 60 200 at 640×480:
//   iwasaki                         P·S·T = 3.61 M steps      10 724 ms  → 2.97 µs per step
//   iwasaki_vertex,  3 362 vertices  V·S·T = 0.20 M          436 ms
//   iwasaki_vertex, 13 122 vertices  V·S·T = 0.79 M          824 ms
// Per-vertex step: (824 − 436) ms / 0.59 M = 0.66 µs = 0.22 per-pixel steps. The draw: 436 ms −
// 0.20 M × 0.66 µs = 302 ms over P, 5.0 µs = 1.7 per-pixel steps per cloth pixel (it holds the
// frame's costs outside the cloth too: the floor, the clear). The swatch (unoccluded, large
// triangles; same run settings) shades a vertex step for 0.61 µs (levels 2 → 3: 154 → 608 ms) but a
// pixel step for only 0.92 µs (6 442 ms over 116 000 cloth pixels): the occluded pillow's pixels
// pay for their three vertices' visibility and for ~9-pixel triangles, and per-pixel work there is
// the product's case. At these constants a per-vertex pillow costs as much as per-pixel at about
// 266 000 vertices (level 3: 206 000); on a frame with 16 times fewer cloth pixels (160×120),
// level 2 already costs more, as measured (docs/bench/mesh_density/).

namespace weft {

inline constexpr int kKioskWidth = 640, kKioskHeight = 480;

inline constexpr double kVertexStepCost = 0.22;      // one vertex × SG × sample, in per-pixel steps
inline constexpr double kVertexDrawPixelCost = 1.7;  // one cloth pixel of the per-vertex draw, in per-pixel steps

// Cloth pixels of a frame scaled from `width`×`height` to the kiosk's 640×480 (the same view:
// pixels scale with the area).
double kiosk_cloth_pixels(double cloth_pixels, int width, int height);

// `vertex_samples`: Σ over the cloth's vertices of their fabric's tangent samples (both threads);
// `vertices`: the cloth's vertex count (their mean is the per-pixel T̄).
double per_pixel_work(double kiosk_pixels, int sgs, double vertex_samples, double vertices);
double per_vertex_work(double kiosk_pixels, int sgs, double vertex_samples);

}  // namespace weft
