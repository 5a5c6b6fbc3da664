#pragma once
// Registry entries of seed 000's method: `iwasaki` (per pixel) and `iwasaki_vertex` (per vertex,
// radiance interpolated: same tables, a fraction of the cost). Both draw from a bundle's seed
// 000 tables (iwasaki_cloth.h) and share one C++ twin (iwasaki.h); the bench's C++ evaluation
// is iwasaki's, without visibility, on small tables baked in memory.
#include "methods/runtime_method.h"

namespace weft::methods {
RuntimeMethod iwasaki_method();
RuntimeMethod iwasaki_vertex_method();
// iwasaki with each SG's exact visible share (V_k from the bundle's visibility masks, blended over
// the triangle's vertices by barycentrics) in place of the SDF's linearised H.
RuntimeMethod iwasaki_mask_method();
// iwasaki_vertex with each SG's exact visible share per vertex (V_k from the bundle's visibility
// masks, SgVisibility::from_mask) in place of the SDF's linearised H.
RuntimeMethod iwasaki_vertex_mask_method();
// iwasaki with the broad SGs (λ < kBroadLobeSharpness) shaded by quadrature of the model per vertex,
// each cell's visibility from the bundle's masks (broad_lobe_quadrature.h), interpolated by
// barycentrics; iwasaki per pixel (SDF visibility) over the others.
RuntimeMethod iwasaki_quadrature_method();
// The same per vertex: iwasaki_vertex over the sharper SGs plus the broad lobes' quadrature.
RuntimeMethod iwasaki_vertex_quadrature_method();
}  // namespace weft::methods
