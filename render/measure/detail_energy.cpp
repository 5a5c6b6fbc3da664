#include "measure/detail_energy.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace weft::bench {

namespace {

std::vector<double> luminance(const Image& image) {
  std::vector<double> y(image.pixels.size());
  for (size_t i = 0; i < y.size(); ++i) y[i] = glm::dot(image.pixels[i], glm::dvec3(0.2126, 0.7152, 0.0722));
  return y;
}

// Separable Gaussian of kDetailBlurSigma, ±3σ, the edge pixels repeated.
std::vector<double> blurred(const std::vector<double>& y, int w, int h) {
  const int r = int(std::ceil(3.0 * kDetailBlurSigma));
  std::vector<double> kernel(2 * r + 1);
  double total = 0.0;
  for (int k = -r; k <= r; ++k) total += kernel[k + r] = std::exp(-0.5 * k * k / (kDetailBlurSigma * kDetailBlurSigma));
  for (double& k : kernel) k /= total;
  std::vector<double> across(y.size()), out(y.size());
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      double s = 0.0;
      for (int k = -r; k <= r; ++k) s += kernel[k + r] * y[size_t(j) * w + std::clamp(i + k, 0, w - 1)];
      across[size_t(j) * w + i] = s;
    }
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      double s = 0.0;
      for (int k = -r; k <= r; ++k) s += kernel[k + r] * across[size_t(std::clamp(j + k, 0, h - 1)) * w + i];
      out[size_t(j) * w + i] = s;
    }
  return out;
}

}  // namespace

DetailBlocks detail_energy(const Image& image) {
  if (image.width <= 0 || image.height <= 0) throw std::invalid_argument("detail energy: an empty image");
  const int w = image.width, h = image.height;
  const std::vector<double> y = luminance(image), b = blurred(y, w, h);
  DetailBlocks out;
  out.columns = (w + kDetailBlock - 1) / kDetailBlock;
  out.rows = (h + kDetailBlock - 1) / kDetailBlock;
  out.energy.assign(size_t(out.columns) * out.rows, 0.0);
  std::vector<size_t> count(out.energy.size(), 0);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const size_t k = size_t(j / kDetailBlock) * out.columns + i / kDetailBlock;
      const double d = y[size_t(j) * w + i] - b[size_t(j) * w + i];
      out.energy[k] += d * d;
      ++count[k];
    }
  for (size_t k = 0; k < out.energy.size(); ++k) out.energy[k] /= double(count[k]);
  return out;
}

DetailRatio detail_ratio(const Image& method, const Image& reference, double limit) {
  if (method.width != reference.width || method.height != reference.height)
    throw std::invalid_argument("detail ratio: images of different sizes");
  const DetailBlocks m = detail_energy(method), r = detail_energy(reference);
  double mean = 0.0;
  for (const auto& p : reference.pixels) mean += glm::dot(p, glm::dvec3(0.2126, 0.7152, 0.0722));
  mean /= double(reference.pixels.size());
  const double floor = std::max(1e-30, 1e-4 * mean * mean);
  DetailRatio out;
  out.blocks = m.energy.size();
  for (size_t k = 0; k < m.energy.size(); ++k) {
    const double ratio = m.energy[k] / std::max(r.energy[k], floor);
    if (ratio > limit) ++out.over;
    if (ratio > out.worst) {
      out.worst = ratio;
      out.worst_column = int(k % size_t(m.columns));
      out.worst_row = int(k / size_t(m.columns));
    }
  }
  return out;
}

}  // namespace weft::bench
