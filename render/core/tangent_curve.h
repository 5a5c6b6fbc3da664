#pragma once
// Tangent curve of one thread (Sadeghi 2013 Table II, docs/design.md §2): a piecewise-linear tilt
// α(s) over arc length s. Offsets o_0..o_m in degrees, segment lengths ℓ_0..ℓ_{m-1}; a zero
// length is a jump, so no sample ever lands inside it.
#include <string>
#include <vector>

namespace weft {

class TangentCurve {
public:
  // Throws std::invalid_argument when lengths.size() != offsets.size()-1 (a single offset is
  // allowed with no lengths: a straight thread), a length is negative or not finite, or the
  // total length is zero.
  TangentCurve(std::vector<double> offsets_deg, std::vector<double> lengths);
  TangentCurve() : TangentCurve({0.0}, {}) {}

  double total_length() const { return total_; }  // Λ
  // Tilt α in radians at arc length s ∈ [0, Λ].
  double tilt_at(double s) const;
  // The N tilts a method with N samples uses: α((k+½)·Λ/N), k = 0..N-1.
  std::vector<double> sample_tilts(int n) const;
  // For each of those samples, the RMS of α(s) − α((k+½)·Λ/N) over the arc it stands for,
  // s ∈ [k·Λ/N, (k+1)·Λ/N] (radians): 0 on a straight stretch, Δα/√12 on a ramp of Δα per sample.
  std::vector<double> sample_tilt_spreads(int n) const;

  const std::vector<double>& offsets_deg() const { return offsets_; }
  const std::vector<double>& lengths() const { return lengths_; }

private:
  std::vector<double> offsets_;
  std::vector<double> lengths_;
  double total_ = 0.0;
};

}  // namespace weft
