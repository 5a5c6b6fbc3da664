#include "capture/response_calibration.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "image/texture_image.h"

namespace weft {

double ResponseModel::sensor(std::uint8_t code) const { return std::pow(srgb_to_linear(code / 255.0), beta); }

glm::dvec3 ResponseModel::relative(const std::array<std::uint8_t, 3>& code, double r2) const {
  const double falloff = 1.0 - vignetting * r2;
  return glm::dvec3(sensor(code[0]), sensor(code[1]), sensor(code[2])) / (falloff * scale);
}

CameraResponse ResponseModel::curve() const {
  CameraResponse r;
  for (int z = 0; z < 256; ++z) r.inverse_table[z] = static_cast<float>(sensor(static_cast<std::uint8_t>(z)));
  return r;
}

namespace {

constexpr int kMinUsable = 4;

bool usable(const ResponseSample& s) {
  if (s.count == 0 || s.reflectance <= 0) return false;
  for (int c = 0; c < 3; ++c) {
    std::uint32_t clipped = 0, dark = 0;
    for (int z = 250; z < 256; ++z) clipped += s.histogram[c][z];
    for (int z = 0; z < 4; ++z) dark += s.histogram[c][z];
    if (clipped * 20 >= s.count || dark * 2 >= s.count) return false;
  }
  return true;
}

struct Used {
  const ResponseSample* sample;
  size_t photo;
};

struct GridPoint {
  double cost = std::numeric_limits<double>::infinity();
  double beta = 1, v = 0;
  std::vector<glm::dvec3> log_scale;
};

// The best (β, v) on the grid beta0 + i·dbeta (i < nbeta) × v0 + j·dv (j < nv), each photo's
// log s_c the mean of its samples' log ratios.
GridPoint search(const std::vector<Used>& used, size_t photos, double beta0, double dbeta, int nbeta, double v0, double dv, int nv) {
  GridPoint best;
  std::vector<glm::dvec3> log_mean(used.size()), log_scale(photos);
  std::vector<int> per_photo(photos, 0);
  for (const Used& u : used) ++per_photo[u.photo];
  for (int bi = 0; bi < nbeta; ++bi) {
    ResponseModel m;
    m.beta = beta0 + dbeta * bi;
    std::array<double, 256> table;
    for (int z = 0; z < 256; ++z) table[z] = m.sensor(static_cast<std::uint8_t>(z));
    for (size_t i = 0; i < used.size(); ++i)
      for (int c = 0; c < 3; ++c) {
        double sum = 0;
        for (int z = 0; z < 256; ++z) sum += used[i].sample->histogram[c][z] * table[z];
        log_mean[i][c] = std::log(std::max(sum / used[i].sample->count, 1e-6) / used[i].sample->reflectance);
      }
    for (int vi = 0; vi < nv; ++vi) {
      const double v = v0 + dv * vi;
      if (v < 0 || v >= 0.95) continue;
      std::fill(log_scale.begin(), log_scale.end(), glm::dvec3(0));
      for (size_t i = 0; i < used.size(); ++i) log_scale[used[i].photo] += log_mean[i] - std::log(1 - v * used[i].sample->r2);
      for (size_t p = 0; p < photos; ++p) log_scale[p] /= std::max(per_photo[p], 1);
      double cost = 0;
      for (size_t i = 0; i < used.size(); ++i) {
        const glm::dvec3 r = log_mean[i] - std::log(1 - v * used[i].sample->r2) - log_scale[used[i].photo];
        cost += glm::dot(r, r);
      }
      if (cost < best.cost) best = {cost, m.beta, v, log_scale};
    }
  }
  return best;
}

GridPoint fit(const std::vector<Used>& used, size_t photos) {
  const GridPoint coarse = search(used, photos, 0.6, 0.01, 101, 0.0, 0.01, 61);
  return search(used, photos, coarse.beta - 0.01, 0.001, 21, coarse.v - 0.01, 0.0005, 41);
}

// Each sample's RMS log residual per channel under `g`.
std::vector<double> residuals(const std::vector<Used>& used, const GridPoint& g) {
  ResponseModel m;
  m.beta = g.beta;
  std::vector<double> out;
  for (const Used& u : used) {
    double sq = 0;
    for (int c = 0; c < 3; ++c) {
      double sum = 0;
      for (int z = 0; z < 256; ++z) sum += u.sample->histogram[c][z] * m.sensor(static_cast<std::uint8_t>(z));
      const double r = std::log(std::max(sum / u.sample->count, 1e-6) / u.sample->reflectance) - std::log(1 - g.v * u.sample->r2) -
                       g.log_scale[u.photo][c];
      sq += r * r;
    }
    out.push_back(std::sqrt(sq / 3));
  }
  return out;
}

}  // namespace

int usable_samples(const std::vector<ResponseSample>& samples) {
  return static_cast<int>(std::count_if(samples.begin(), samples.end(), usable));
}

ResponseFit fit_response(const std::vector<ResponseSample>& samples) { return fit_shared_response({samples}).front(); }

std::vector<ResponseFit> fit_shared_response(const std::vector<std::vector<ResponseSample>>& photos) {
  std::vector<Used> used;
  for (size_t p = 0; p < photos.size(); ++p) {
    const int n = usable_samples(photos[p]);
    if (n < kMinUsable)
      throw std::runtime_error("too few usable grey samples on the card (" + std::to_string(n) + ")");
    for (const ResponseSample& s : photos[p])
      if (usable(s)) used.push_back({&s, p});
  }
  GridPoint g = fit(used, photos.size());
  // Outliers: more than 4× the median residual and 3 % off (a shadow, a smudge; the darkest
  // patch's noise stays under it). A photo keeps at least its minimum.
  const std::vector<double> res = residuals(used, g);
  std::vector<double> sorted = res;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const double limit = std::max(4.0 * sorted[sorted.size() / 2], 0.03);
  std::vector<int> kept(photos.size(), 0);
  std::vector<Used> inliers;
  for (size_t i = 0; i < used.size(); ++i)
    if (res[i] <= limit) {
      inliers.push_back(used[i]);
      ++kept[used[i].photo];
    }
  if (inliers.size() < used.size() && *std::min_element(kept.begin(), kept.end()) >= kMinUsable) {
    used = std::move(inliers);
    g = fit(used, photos.size());
  }
  const std::vector<double> final_res = residuals(used, g);
  std::vector<ResponseFit> out(photos.size());
  std::vector<double> sq(photos.size(), 0);
  for (size_t i = 0; i < used.size(); ++i) {
    ++out[used[i].photo].samples_used;
    sq[used[i].photo] += final_res[i] * final_res[i];
  }
  for (size_t p = 0; p < photos.size(); ++p) {
    out[p].model.beta = g.beta;
    out[p].model.vignetting = g.v;
    out[p].model.scale = glm::exp(g.log_scale[p]);
    out[p].rms_log_error = std::sqrt(sq[p] / std::max(out[p].samples_used, 1));
  }
  return out;
}

}  // namespace weft
