#pragma once
// Cheaper settings cut from a richer bake without baking again (bake/selection/scene_selection.h measures
// them): weighting tables with fewer sharpness levels (every k-th of the baked log-spaced levels,
// both ends kept) and a looser SVD target (each table's factors cut to the smallest rank that
// meets it: the columns come in decreasing singular value, so the cut is the best rank-r
// approximation and its error is exact), and visibility PCA with fewer terms.
#include "runtime/object_visibility.h"
#include "runtime/weighting_tables.h"

namespace weft {

// Levels 0, stride, 2·stride, ... of `full` (its level count − 1 must be a multiple of
// `stride`); each table cut to the smallest rank with ‖T − U_r·V_rᵀ‖_F/‖T‖_F ≤ svd_error (never
// below what `full` stored). Throws std::invalid_argument for a stride that does not divide.
WeightingTables truncate_tables(const WeightingTables& full, double svd_error, int level_stride);

// The fewest leading PCA terms whose RMS reconstruction error (radians, over all vertices and
// cells) is ≤ rms_error (all of `full`'s when none fewer is); rms_error is that of the terms
// kept (exact: the basis is orthonormal), max_error a bound (`full`'s plus the dropped terms' largest).
ObjectVisibility truncate_visibility(const ObjectVisibility& full, double rms_error);

}  // namespace weft
