#pragma once
// Where each thread lies in one repeat of the weave (docs/design.md §2, "Resolved weave"): the
// tile [0,1)² with s along the warp u and t along the weft v holds `rows` warp yarns, one per
// band of height 1/rows. In row r the warp floats over s ∈ [r·shift/rows, r·shift/rows + f)
// (mod 1), f = a_1/(a_1 + a_2), and the weft comes up in the rest of the row: one weft float per
// row, running along t across it. Each float's yarn fills the middle w = a_1 + a_2 of its width;
// the sides are gap. So thread j covers exactly a_j of the tile, its visible float runs along its
// tangent curve uniformly in arc length, and the tile's area average of any per-sample quantity
// is Σ_j a_j ⟨·⟩_j: the fabric-level model is the resolved one averaged over the repeat.
#include "core/fabric.h"

namespace weft {

// What lies at one point of the tile.
struct WeaveSample {
  int thread = -1;    // 0 warp, 1 weft, −1 gap
  double arc = 0.0;   // position along the float as a fraction of the curve's length Λ_j, [0, 1)
  double across = 0.0;  // position across the yarn, −½..½ of its width (0 on the yarn's crest)
};

class WeaveLayout {
public:
  // The fabric's weave (Fabric::weave), with rows and shift chosen from the coverages where it
  // leaves them at 0: near-equal coverages a plain weave (2 rows), 0.6–0.8 a twill (4 rows,
  // shift 1), beyond that a five-end satin (5 rows, shift 2).
  explicit WeaveLayout(const Fabric& fabric);

  // (s, t) in tile units, any real numbers (the tile repeats).
  WeaveSample at(double s, double t) const;

  int rows() const { return rows_; }
  int shift() const { return shift_; }
  double warp_share() const { return warp_share_; }  // f: the share of each row the warp floats over
  double yarn_width() const { return width_; }       // w: the share of a float's width its yarn fills

private:
  int rows_ = 2, shift_ = 1;
  double warp_share_ = 0.5, width_ = 0.66;
};

// The tilt α (radians) of the thread sample at `w` (a thread, not a gap): its curve at w.arc·Λ_j.
double weave_tilt(const Fabric& fabric, const WeaveSample& w);

// The weave's repeat in centimetres: (along s, along t) = (rows/picks per cm, rows/ends per cm).
glm::dvec2 weave_repeat_cm(const Fabric& fabric);

}  // namespace weft
