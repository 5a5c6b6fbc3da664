#include "capture/closeup_shot.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include <Eigen/Dense>

#include "capture/capture_card.h"
#include "capture/capture_rejection.h"
#include "capture/card_samples.h"
#include "image/tone_map.h"

namespace weft {

namespace {

constexpr double kGapLevel = 0.03;        // × the 90th percentile's luminance: a gap, not a thread
constexpr double kLightnessWeight = 0.5;  // log lightness against log chromaticity in the k-means
constexpr int kClipCode = 250;
constexpr int kMinPixels = 2000;
constexpr double kMinShare = 0.02;  // of the inner pixels: a smaller cluster is stray pixels
// The tag's white border lies between 0.5 and 0.625 of the black square's side from its centre
// (Chebyshev); a margin each side for the lens's blur and the corners' detection.
constexpr double kBorderIn = 0.53, kBorderOut = 0.6;
// The share of the swatch's pixels that may clip before its mean is no longer its level.
constexpr double kLevelClipped = 0.002;

struct TwoMeans {
  std::vector<int> label;
  std::array<Eigen::Vector3d, 2> centre;
};

// Two means from the two ends of the points' principal axis (10th and 90th percentile), a plain
// Lloyd iteration: OpenCV's kmeans would bring a large library for these few lines.
TwoMeans two_means(const std::vector<Eigen::Vector3d>& x) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& p : x) mean += p;
  mean /= static_cast<double>(x.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const auto& p : x) cov += (p - mean) * (p - mean).transpose();
  const Eigen::Vector3d axis = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(cov).eigenvectors().col(2);
  std::vector<double> along;
  for (const auto& p : x) along.push_back((p - mean).dot(axis));
  std::sort(along.begin(), along.end());
  TwoMeans m{std::vector<int>(x.size(), 0), {mean + axis * along[along.size() / 10], mean + axis * along[along.size() * 9 / 10]}};
  for (int iteration = 0; iteration < 30; ++iteration) {
    std::array<Eigen::Vector3d, 2> sum{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
    std::array<int, 2> count{0, 0};
    bool moved = false;
    for (size_t i = 0; i < x.size(); ++i) {
      const int l = (x[i] - m.centre[1]).squaredNorm() < (x[i] - m.centre[0]).squaredNorm();
      moved = moved || l != m.label[i];
      m.label[i] = l;
      sum[l] += x[i];
      ++count[l];
    }
    for (int c = 0; c < 2; ++c)
      if (count[c] > 0) m.centre[c] = sum[c] / count[c];
    if (!moved && iteration > 0) break;
  }
  return m;
}

// The histogram of the points along the line through the two centres (0 at the first, 1 at the
// second), lightly smoothed: its lowest bin between the two peaks over the lower peak.
double valley_between(const std::vector<Eigen::Vector3d>& x, const TwoMeans& m) {
  constexpr int kBins = 40;  // over [−0.5, 1.5]
  const Eigen::Vector3d d = m.centre[1] - m.centre[0];
  if (d.squaredNorm() <= 0) return 1;
  std::array<double, kBins> h{};
  for (const auto& p : x) {
    const double t = (p - m.centre[0]).dot(d) / d.squaredNorm();
    const int b = static_cast<int>(std::floor((t + 0.5) / 2.0 * kBins));
    if (b >= 0 && b < kBins) h[b] += 1;
  }
  std::array<double, kBins> s{};
  for (int b = 0; b < kBins; ++b) s[b] = (h[std::max(b - 1, 0)] + 2 * h[b] + h[std::min(b + 1, kBins - 1)]) / 4;
  const auto mid = s.begin() + kBins / 2;
  const auto peak0 = std::max_element(s.begin(), mid), peak1 = std::max_element(mid, s.end());
  const double low = *std::min_element(peak0, peak1 + 1);
  return std::min(*peak0, *peak1) > 0 ? low / std::min(*peak0, *peak1) : 1;
}

// The close-up's swatch level over its tag's white border (CloseupClusters::level): the border's
// median (the lens blurs its edges into the ink and the cloth), the swatch's mean over the whole
// frame off the tag, gaps and highlights included, as the photos' cells average them.
template <class Read>
std::optional<glm::dvec3> swatch_level(const Photo& photo, const CloseupScale& scale, const Read& read) {
  const CaptureCard& card = capture_card();
  const double side = card.closeup_tag.size * scale.px_per_mm;  // the black square's, pixels
  std::array<std::vector<double>, 3> border;
  glm::dvec3 sum(0);
  long swatch = 0, clipped = 0;
  for (int y = 0; y < photo.height; ++y)
    for (int x = 0; x < photo.width; ++x) {
      const glm::dvec2 p(x + 0.5, y + 0.5), d = glm::abs(scale.in_tag_axes(p));
      const double r = std::max(d.x, d.y) / side;
      const std::optional<glm::dvec3> v = read(x, y);
      if (r >= kBorderIn && r <= kBorderOut) {
        if (!v) return std::nullopt;
        for (int c = 0; c < 3; ++c) border[c].push_back((*v)[c]);
      } else if (!scale.covers(p)) {
        ++swatch;
        if (v)
          sum += *v;
        else
          ++clipped;
      }
    }
  if (border[0].size() < 100 || swatch == 0 || static_cast<double>(clipped) / swatch > kLevelClipped) return std::nullopt;
  glm::dvec3 paper;
  for (int c = 0; c < 3; ++c) {
    std::nth_element(border[c].begin(), border[c].begin() + border[c].size() / 2, border[c].end());
    paper[c] = border[c][border[c].size() / 2];
  }
  if (glm::any(glm::lessThanEqual(paper, glm::dvec3(0)))) return std::nullopt;
  return sum / static_cast<double>(swatch) / paper * card.paper_reflectance;
}

}  // namespace

CloseupClusters measure_closeup(const Photo& photo, const ResponseModel& response, const std::string& name) {
  const int x0 = photo.width / 10, x1 = photo.width - photo.width / 10;
  const int y0 = photo.height / 10, y1 = photo.height - photo.height / 10;
  const int w = x1 - x0, h = y1 - y0;
  CloseupClusters out;
  out.scale = find_closeup_scale(photo);
  // Whether pixel (x, y) is the tag's paper; its relative linear value, or nothing when clipped.
  auto on_tag = [&](int x, int y) { return out.scale && out.scale->covers({x + 0.5, y + 0.5}); };
  auto read = [&](int x, int y) -> std::optional<glm::dvec3> {
    const std::array<std::uint8_t, 3> code{photo.at(x, y, 0), photo.at(x, y, 1), photo.at(x, y, 2)};
    if (std::max({code[0], code[1], code[2]}) >= kClipCode) return std::nullopt;
    return response.relative(code, image_radius2(photo, x + 0.5, y + 0.5));
  };
  auto inner = [&](int x, int y) { return x >= x0 && x < x1 && y >= y0 && y < y1; };
  std::vector<glm::dvec3> value(static_cast<size_t>(w) * h);
  std::vector<double> lum(value.size(), -1);  // −1: clipped, or the scale tag
  long clipped = 0, swatch = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      if (on_tag(x, y)) continue;
      ++swatch;
      const size_t i = static_cast<size_t>(y - y0) * w + (x - x0);
      const std::optional<glm::dvec3> v = read(x, y);
      if (!v) {
        ++clipped;
        continue;
      }
      value[i] = *v;
      lum[i] = luminance(value[i]);
    }
  if (swatch == 0 || static_cast<double>(clipped) / swatch > 0.02)
    throw CaptureRejection(name + ": saturated (" + std::to_string(swatch ? 100.0 * clipped / swatch : 100.0) +
                           " % of its pixels clipped; lower the exposure)");
  std::vector<double> sorted;
  for (double l : lum)
    if (l >= 0) sorted.push_back(l);
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() * 9 / 10, sorted.end());
  const double floor = kGapLevel * sorted[sorted.size() * 9 / 10];

  // The weave's spectrum, where the tag gives the millimetres, over the whole frame (the disc beside
  // the tag wants all the room there is): the gaps are the yarns' clearest edges, so they stay in
  // (at the floor), and the log keeps a float's highlight from outweighing them.
  if (out.scale) {
    const size_t n = static_cast<size_t>(photo.width) * photo.height;
    std::vector<double> log_lum(n, 0.0);
    std::vector<bool> use(n, false);
    for (int y = 0; y < photo.height; ++y)
      for (int x = 0; x < photo.width; ++x) {
        double l = -1;  // the middle's pixels were read above
        if (inner(x, y))
          l = lum[static_cast<size_t>(y - y0) * w + (x - x0)];
        else if (!on_tag(x, y))
          if (const std::optional<glm::dvec3> v = read(x, y)) l = luminance(*v);
        if (l < 0) continue;
        const size_t i = static_cast<size_t>(y) * photo.width + x;
        log_lum[i] = std::log(std::max(l, floor));
        use[i] = true;
      }
    out.spectrum = closeup_spectrum(log_lum, use, photo.width, photo.height, *out.scale);
  }

  if (out.scale) out.level = swatch_level(photo, *out.scale, read);

  // The thread pixels.
  std::vector<size_t> index;
  long gaps = 0;
  for (size_t i = 0; i < value.size(); ++i) {
    if (lum[i] < 0) continue;
    if (lum[i] <= floor || glm::any(glm::lessThanEqual(value[i], glm::dvec3(0))))
      ++gaps;
    else
      index.push_back(i);
  }
  if (index.size() < static_cast<size_t>(kMinPixels))
    throw CaptureRejection(name + ": too few thread pixels (" + std::to_string(index.size()) +
                           "); fill the frame with the swatch, in focus, from straight above");
  out.gap_share = static_cast<double>(gaps) / (gaps + index.size());

  // Each split: k-means on log chromaticity and `lightness`-weighted log lightness; its means over
  // the inner pixels only (a pixel on a boundary mixes both threads: the lens, the sensor, the JPEG).
  for (const double lightness : {kLightnessWeight, 0.0}) {
    std::vector<Eigen::Vector3d> features;
    for (size_t i : index) {
      const glm::dvec3 v = glm::log(value[i]);
      features.emplace_back(v.r - v.g, v.b - v.g, lightness * std::log(lum[i]));
    }
    const TwoMeans clusters = two_means(features);
    std::vector<int> label(value.size(), -1);
    for (size_t k = 0; k < index.size(); ++k) label[index[k]] = clusters.label[k];
    CloseupSplit split;
    split.lightness = lightness > 0;
    std::array<glm::dvec3, 2> sum{glm::dvec3(0), glm::dvec3(0)};
    std::array<int, 2> count{0, 0};
    for (int y = 1; y + 1 < h; ++y)
      for (int x = 1; x + 1 < w; ++x) {
        const size_t i = static_cast<size_t>(y) * w + x;
        const int l = label[i];
        if (l < 0 || label[i - 1] != l || label[i + 1] != l || label[i - w] != l || label[i + w] != l) continue;
        sum[l] += value[i];
        ++count[l];
      }
    split.pixels = count[0] + count[1];
    if (split.pixels < kMinPixels / 2)
      throw CaptureRejection(name + ": the threads are too fine (" + std::to_string(split.pixels) +
                             " pixels inside a thread); bring the camera closer so each thread spans several pixels");
    for (int c = 0; c < 2; ++c) {
      split.mean[c] = count[c] > 0 ? sum[c] / static_cast<double>(count[c]) : sum[1 - c] / static_cast<double>(count[1 - c]);
      split.share[c] = static_cast<double>(count[c]) / split.pixels;
    }
    // A cluster of a few stray pixels is no thread: one colour.
    split.valley = std::min(split.share[0], split.share[1]) < kMinShare ? 1.0 : valley_between(features, clusters);
    out.splits.push_back(split);
  }
  return out;
}

}  // namespace weft
