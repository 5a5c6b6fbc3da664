#pragma once
// Registry entries of the iwasaki family, drawn from a bundle's weighting tables (iwasaki_cloth.h)
// and sharing one C++ twin (iwasaki.h); the bench's C++ evaluation is iwasaki's, without
// visibility, on small tables baked in memory. Eight rungs: evaluated per pixel (`iwasaki`) or
// per vertex and interpolated (`iwasaki_vertex`: same tables, a fraction of the cost), each with
// what it reads from the bundle's visibility masks:
//  - nothing: the SDF's linearised H per SG (the paper's visibility);
//  - `_mask`: each SG's exact visible share V_k per vertex (SgVisibility::from_mask), blended
//    over the triangle's vertices per pixel, in place of the SDF;
//  - `_quadrature`: the broad SGs (λ < kBroadLobeSharpness) by quadrature of the model per vertex,
//    each cell's visibility from the masks (broad_lobe_quadrature.h); the SDF for the others;
//  - `_mask_quadrature`: both, the broad SGs by quadrature and V_k for the others: exact
//    visibility where the SDF's one linear boundary fails (thin occluders, crevices), but V_k is
//    one number per vertex and SG, so a sharp lobe's shadow edge is interpolated across triangles
//    where the SDF places it per pixel.
#include <vector>

#include "methods/runtime_method.h"

namespace weft::methods {
// The per-pixel rungs, then the per-vertex ones; `iwasaki` first.
std::vector<RuntimeMethod> iwasaki_methods();
}  // namespace weft::methods
