// The weave layer's reach per vertex (methods/weave/weave_reach.h), for its per-vertex passes: a
// vertex whose footprint in this view (WeaveReach::footprints, at its pass texel of
// u_weave_reach) reaches the coarse footprint shows no thread's detail near it (the draw fades
// those pixels to 1), so it needs no terms. u_weave_reach_before: the draw's before, where a
// vertex that was out of reach holds no kept value to reuse.
uniform highp sampler2D u_weave_reach;
uniform highp sampler2D u_weave_reach_before;
uniform float u_weave_coarse;  // kWeaveCoarseFootprint
bool weave_vertex_unresolved(ivec2 texel) { return texelFetch(u_weave_reach, texel, 0).r >= u_weave_coarse; }
bool weave_vertex_newly_resolved(ivec2 texel) { return texelFetch(u_weave_reach_before, texel, 0).r >= u_weave_coarse; }
