#include "core/cloth_bsdf.h"

#include <algorithm>
#include <stdexcept>

namespace weft {

ClothBsdf::ClothBsdf(const Fabric& fabric, std::array<int, 2> samples) : fabric_(fabric) {
  for (int j = 0; j < 2; ++j) {
    tilts_[j] = fabric_.threads[j].curve.sample_tilts(samples[j]);
    spreads_[j] = fabric_.threads[j].curve.sample_tilt_spreads(samples[j]);
    const size_t n = tilts_[j].size();
    multiplicity_[j].assign(n, 0);
    for (size_t k = 0; k < n; ++k) {
      size_t first = 0;
      while (tilts_[j][first] != tilts_[j][k] || spreads_[j][first] != spreads_[j][k]) ++first;
      ++multiplicity_[j][first];
    }
  }
}

ClothBsdf::Point::Point(const ClothBsdf& bsdf, const SurfaceFrame& frame) : bsdf_(&bsdf), frame_(frame) {
  const int n = bsdf.total_samples();
  frames_.reserve(n);
  for (int j = 0; j < 2; ++j)
    for (double alpha : bsdf.tilts_[j]) frames_.push_back(thread_frame(frame, j, alpha));
  in_.resize(n);
  out_.resize(n);
  proj_.resize(n);
}

double ClothBsdf::Point::prepare(const dvec3& wi, const dvec3& wo) {
  const auto& threads = bsdf_->fabric_.threads;
  double q = (1.0 - threads[0].coverage - threads[1].coverage) * std::max(glm::dot(frame_.n, wo), 0.0);
  size_t s = 0;
  for (int j = 0; j < 2; ++j) {
    const int n = bsdf_->sample_count(j);
    double sum = 0.0;
    for (int k = 0; k < n; ++k, ++s) {
      in_[s] = fiber_angles(frames_[s], wi);
      out_[s] = fiber_angles(frames_[s], wo);
      proj_[s] = projection(in_[s], out_[s]);
      sum += proj_[s];
    }
    q += threads[j].coverage * sum / n;
  }
  return q;
}

double ClothBsdf::Point::q(const dvec3& wi, const dvec3& wo) { return prepare(wi, wo); }

double ClothBsdf::Point::weights(const dvec3& wi, const dvec3& wo, std::span<double> w) {
  if (w.size() != frames_.size()) throw std::invalid_argument("weights: span size must equal total_samples()");
  const double q = prepare(wi, wo);
  size_t s = 0;
  for (int j = 0; j < 2; ++j) {
    const double a = bsdf_->fabric_.threads[j].coverage;
    for (int k = 0; k < bsdf_->sample_count(j); ++k, ++s)
      w[s] = q > kQFloor ? a * masking(in_[s], out_[s]) * proj_[s] / q : 0.0;
  }
  return q;
}

ClothBsdf::Point::Split ClothBsdf::Point::integrand_split(const dvec3& wi, const dvec3& wo) {
  Split out;
  if (glm::dot(frame_.n, wi) <= 0.0 || glm::dot(frame_.n, wo) <= 0.0) return out;
  const double q = prepare(wi, wo);
  if (q <= kQFloor) return out;
  size_t s = 0;
  for (int j = 0; j < 2; ++j) {
    const ThreadParams& p = bsdf_->fabric_.threads[j];
    const int n = bsdf_->sample_count(j);
    glm::dvec2 sum(0.0);
    for (int k = 0; k < n; ++k, ++s) {
      if (proj_[s] <= 0.0) continue;
      const double w = p.coverage * masking(in_[s], out_[s]) * proj_[s] / q;
      if (w <= 0.0) continue;
      sum += scattering_split(p, in_[s], out_[s]) * (w * std::cos(in_[s].theta));
    }
    out.surface += sum.x / double(n);
    out.volume[j] = sum.y / double(n);
  }
  return out;
}

dvec3 ClothBsdf::Point::integrand(const dvec3& wi, const dvec3& wo, const std::array<dvec3, 2>& tint) {
  const Split s = integrand_split(wi, wo);
  const auto& t = bsdf_->fabric_.threads;
  return dvec3(s.surface) + s.volume[0] * t[0].albedo * tint[0] + s.volume[1] * t[1].albedo * tint[1];
}

dvec3 ClothBsdf::Point::integrand(const dvec3& wi, const dvec3& wo) { return integrand(wi, wo, {dvec3(1.0), dvec3(1.0)}); }

dvec3 ClothBsdf::Point::resolved_integrand(int thread, double tilt, const dvec3& wi, const dvec3& wo) {
  if (glm::dot(frame_.n, wi) <= 0.0 || glm::dot(frame_.n, wo) <= 0.0) return dvec3(0.0);
  const double q = prepare(wi, wo);
  if (q <= kQFloor) return dvec3(0.0);
  return resolved_scattering(thread, tilt, wi, wo) / q;
}

dvec3 ClothBsdf::Point::resolved_scattering(int thread, double tilt, const dvec3& wi, const dvec3& wo) const {
  if (glm::dot(frame_.n, wi) <= 0.0 || glm::dot(frame_.n, wo) <= 0.0) return dvec3(0.0);
  const ThreadFrame f = thread_frame(frame_, thread, tilt);
  const FiberAngles in = fiber_angles(f, wi), out = fiber_angles(f, wo);
  const double p = projection(in, out);
  if (p <= 0.0) return dvec3(0.0);
  const double w = masking(in, out) * p;
  if (w <= 0.0) return dvec3(0.0);
  return scattering(bsdf_->fabric_.threads[thread], in, out) * (w * std::cos(in.theta));
}

}  // namespace weft
