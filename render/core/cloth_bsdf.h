#pragma once
// The whole fabric's response: both threads' tangent samples combined with Sadeghi's
// reweighting (docs/design.md §2: Q, W, and the integrand of L_o). One implementation, used by
// the reference, the baker and the tests.
#include <span>
#include <vector>

#include "core/fabric.h"

namespace weft {

class ClothBsdf {
public:
  // samples[j]: tangent samples N_j of thread j, taken at arc lengths (k+½)·Λ/N_j.
  ClothBsdf(const Fabric& fabric, std::array<int, 2> samples);
  ClothBsdf(const Fabric& fabric, int samples_per_thread)
      : ClothBsdf(fabric, std::array<int, 2>{samples_per_thread, samples_per_thread}) {}

  const Fabric& fabric() const { return fabric_; }
  int sample_count(int thread) const { return static_cast<int>(tilts_[thread].size()); }
  int total_samples() const { return sample_count(0) + sample_count(1); }
  double tilt(int thread, int k) const { return tilts_[thread][k]; }
  // RMS tilt over the arc sample k stands for (TangentCurve::sample_tilt_spreads).
  double tilt_spread(int thread, int k) const { return spreads_[thread][k]; }
  // How many of the thread's samples have sample k's tilt and spread, where k is the first of
  // them; 0 for the others. Such samples give the same terms (a float's flat run yields several
  // at tilt 0): a sum over samples may take the first times its multiplicity and skip the rest.
  int sample_multiplicity(int thread, int k) const { return multiplicity_[thread][k]; }

  // The model bound to one shading frame. Holds scratch space: one per thread of execution.
  class Point {
  public:
    // Q(ω_i, ω_o) = Σ_j a_j ⟨P⟩_j + (1 − a_1 − a_2) · max(n·ω_o, 0).
    double q(const dvec3& wi, const dvec3& wo);
    // W for every sample, thread 0's first, into `w` (size total_samples()). Returns Q.
    double weights(const dvec3& wi, const dvec3& wo, std::span<double> w);
    // Σ_j ⟨f_s · W · cos θ_i⟩_j: what L_o integrates against L·V over n·ω_i > 0.
    // Zero when ω_i or ω_o is below the surface.
    dvec3 integrand(const dvec3& wi, const dvec3& wo);
    // The same with each thread's albedo multiplied by tint[j] (a texture's texel at the point).
    dvec3 integrand(const dvec3& wi, const dvec3& wo, const std::array<dvec3, 2>& tint);
    // The integrand as surface + Σ_j A_j·volume[j]: its parts per unit albedo.
    struct Split {
      double surface = 0.0;
      std::array<double, 2> volume{0.0, 0.0};
    };
    Split integrand_split(const dvec3& wi, const dvec3& wo);
    // The resolved weave at one point of the repeat (core/weave_layout.h): the one tangent sample
    // that lies there, thread j at tilt α, as f_s · M · P · cos θ_i / Q with the fabric-level Q.
    // Its average over the repeat, thread j covering a_j, is integrand(). Zero below the surface.
    dvec3 resolved_integrand(int thread, double tilt, const dvec3& wi, const dvec3& wo);
    // Its numerator f_s · M · P · cos θ_i (no Q), for methods that take Q from elsewhere.
    dvec3 resolved_scattering(int thread, double tilt, const dvec3& wi, const dvec3& wo) const;
    const SurfaceFrame& frame() const { return frame_; }

  private:
    friend class ClothBsdf;
    Point(const ClothBsdf& bsdf, const SurfaceFrame& frame);
    // Fills in_, out_ and proj_ for every sample and returns Q.
    double prepare(const dvec3& wi, const dvec3& wo);

    const ClothBsdf* bsdf_;
    SurfaceFrame frame_;
    std::vector<ThreadFrame> frames_;
    std::vector<FiberAngles> in_, out_;
    std::vector<double> proj_;
  };

  Point at(const SurfaceFrame& frame) const { return Point(*this, frame); }

private:
  Fabric fabric_;
  std::array<std::vector<double>, 2> tilts_;
  std::array<std::vector<double>, 2> spreads_;
  std::array<std::vector<int>, 2> multiplicity_;
};

}  // namespace weft
