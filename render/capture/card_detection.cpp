#include "capture/card_detection.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Dense>
#include <apriltag.h>
#include <tag36h11.h>

#include "capture/capture_card.h"
#include "capture/capture_rejection.h"

namespace weft {

namespace {

constexpr double kPi = std::numbers::pi;

// The tag's black square corners in card mm, in one cyclic order.
std::array<glm::dvec2, 4> tag_corners_mm(const CardTag& t) {
  const double h = t.size / 2;
  return {t.centre + glm::dvec2(-h, h), t.centre + glm::dvec2(h, h), t.centre + glm::dvec2(h, -h), t.centre + glm::dvec2(-h, -h)};
}

// Direct linear transform with Hartley normalisation: src (plane) → dst (image).
glm::dmat3 fit_homography(const std::vector<glm::dvec2>& src, const std::vector<glm::dvec2>& dst) {
  auto normaliser = [](const std::vector<glm::dvec2>& p) {
    glm::dvec2 mean(0);
    for (const auto& q : p) mean += q;
    mean /= static_cast<double>(p.size());
    double spread = 0;
    for (const auto& q : p) spread += glm::length(q - mean);
    const double s = std::sqrt(2.0) * p.size() / std::max(spread, 1e-12);
    Eigen::Matrix3d T;
    T << s, 0, -s * mean.x, 0, s, -s * mean.y, 0, 0, 1;
    return T;
  };
  const Eigen::Matrix3d Ts = normaliser(src), Td = normaliser(dst);
  Eigen::MatrixXd A(2 * src.size(), 9);
  for (size_t i = 0; i < src.size(); ++i) {
    const Eigen::Vector3d a = Ts * Eigen::Vector3d(src[i].x, src[i].y, 1), b = Td * Eigen::Vector3d(dst[i].x, dst[i].y, 1);
    A.row(2 * i) << -a.x(), -a.y(), -1, 0, 0, 0, b.x() * a.x(), b.x() * a.y(), b.x();
    A.row(2 * i + 1) << 0, 0, 0, -a.x(), -a.y(), -1, b.y() * a.x(), b.y() * a.y(), b.y();
  }
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeFullV);
  const Eigen::VectorXd h = svd.matrixV().col(8);
  Eigen::Matrix3d Hn;
  Hn << h(0), h(1), h(2), h(3), h(4), h(5), h(6), h(7), h(8);
  const Eigen::Matrix3d H = Td.inverse() * Hn * Ts;
  glm::dmat3 out;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) out[c][r] = H(r, c) / H(2, 2);
  return out;
}

// Zhang's constraints on a plane's homography for square pixels and a centred principal point:
// its first two columns through K⁻¹ are orthogonal and of equal length.
std::optional<double> focal_from_homography(const glm::dmat3& H, int width, int height) {
  glm::dmat3 shift(1.0);
  shift[2] = glm::dvec3(-width / 2.0, -height / 2.0, 1);
  const glm::dmat3 G = shift * H;
  const glm::dvec3 h1 = G[0], h2 = G[1];
  std::vector<double> f2;
  if (std::abs(h1.z * h2.z) > 1e-15) f2.push_back(-(h1.x * h2.x + h1.y * h2.y) / (h1.z * h2.z));
  if (std::abs(h1.z * h1.z - h2.z * h2.z) > 1e-15)
    f2.push_back((h2.x * h2.x + h2.y * h2.y - h1.x * h1.x - h1.y * h1.y) / (h1.z * h1.z - h2.z * h2.z));
  double sum = 0;
  int n = 0;
  for (double v : f2)
    if (v > 0) sum += std::sqrt(v), ++n;
  if (n == 0) return std::nullopt;
  return sum / n;
}

CardCamera pose_from_homography(const glm::dmat3& H, double f, int width, int height) {
  Eigen::Matrix3d K;
  K << f, 0, width / 2.0, 0, f, height / 2.0, 0, 0, 1;
  Eigen::Matrix3d He;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) He(r, c) = H[c][r];
  Eigen::Matrix3d B = K.inverse() * He;
  double lambda = 2.0 / (B.col(0).norm() + B.col(1).norm());
  if (B(2, 2) * lambda < 0) lambda = -lambda;  // the card in front of the camera
  Eigen::Matrix3d Rwc;
  Rwc.col(0) = lambda * B.col(0);
  Rwc.col(1) = lambda * B.col(1);
  Rwc.col(2) = Rwc.col(0).cross(Rwc.col(1));
  const Eigen::Vector3d t = lambda * B.col(2);
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(Rwc, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Rwc = svd.matrixU() * svd.matrixV().transpose();
  const Eigen::Vector3d C = -Rwc.transpose() * t;
  CardCamera cam;
  cam.width = width;
  cam.height = height;
  cam.f = f;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) cam.R[r][c] = Rwc(r, c);  // camera → world is Rwcᵀ: glm's [col][row]
  cam.C = glm::dvec3(C.x(), C.y(), C.z());
  return cam;
}

double grey(const Photo& p, double x, double y) {
  const int xi = std::clamp(static_cast<int>(std::floor(x - 0.5)), 0, p.width - 2);
  const int yi = std::clamp(static_cast<int>(std::floor(y - 0.5)), 0, p.height - 2);
  const double ax = std::clamp(x - 0.5 - xi, 0.0, 1.0), ay = std::clamp(y - 0.5 - yi, 0.0, 1.0);
  auto g = [&](int xx, int yy) { return (p.at(xx, yy, 0) + p.at(xx, yy, 1) + p.at(xx, yy, 2)) / 3.0; };
  return (1 - ay) * ((1 - ax) * g(xi, yi) + ax * g(xi + 1, yi)) + ay * ((1 - ax) * g(xi, yi + 1) + ax * g(xi + 1, yi + 1));
}

// The 10–90 % rise of a profile across an edge from paper to ink, in px.
double edge_rise(const Photo& p, glm::dvec2 inside, glm::dvec2 outside) {
  const int n = 64;
  std::vector<double> v(n);
  const double len = glm::length(outside - inside);
  for (int i = 0; i < n; ++i) {
    const glm::dvec2 q = inside + (outside - inside) * (i / (n - 1.0));
    v[i] = grey(p, q.x, q.y);
  }
  const double lo = *std::min_element(v.begin(), v.end()), hi = *std::max_element(v.begin(), v.end());
  if (hi - lo < 20) return len;  // no edge at all: as blurred as can be
  int a = 0, b = n - 1;
  while (a < n - 1 && v[a] < lo + 0.1 * (hi - lo)) ++a;
  while (b > 0 && v[b] > lo + 0.9 * (hi - lo)) --b;
  int first_high = 0;
  while (first_high < n - 1 && v[first_high] < lo + 0.9 * (hi - lo)) ++first_high;
  int last_low = first_high;
  while (last_low > 0 && v[last_low] > lo + 0.1 * (hi - lo)) --last_low;
  return std::abs(first_high - last_low) * len / (n - 1.0);
}

}  // namespace

std::vector<TagSighting> detect_tags(const Photo& photo) {
  std::vector<std::uint8_t> g(static_cast<size_t>(photo.width) * photo.height);
  for (size_t i = 0; i < g.size(); ++i)
    g[i] = static_cast<std::uint8_t>((photo.rgb[3 * i] * 77 + photo.rgb[3 * i + 1] * 150 + photo.rgb[3 * i + 2] * 29) >> 8);
  image_u8_t image{photo.width, photo.height, photo.width, g.data()};
  apriltag_family_t* family = tag36h11_create();
  apriltag_detector_t* detector = apriltag_detector_create();
  apriltag_detector_add_family(detector, family);
  detector->quad_decimate = 1.0f;
  detector->nthreads = 2;
  zarray_t* found = apriltag_detector_detect(detector, &image);
  std::vector<TagSighting> out;
  for (int i = 0; i < zarray_size(found); ++i) {
    apriltag_detection_t* d;
    zarray_get(found, i, &d);
    if (d->id > 5) continue;  // the card prints ids 0–5
    TagSighting s;
    s.id = d->id;
    s.decision_margin = d->decision_margin;
    for (int k = 0; k < 4; ++k) s.corners[k] = glm::dvec2(d->p[k][0], d->p[k][1]);
    out.push_back(s);
  }
  apriltag_detections_destroy(found);
  apriltag_detector_destroy(detector);
  tag36h11_destroy(family);
  return out;
}

glm::dvec2 CardView::to_image(const glm::dvec3& world) const {
  const glm::dvec3 q = H * glm::dvec3(world.x, world.y, 1.0);
  return glm::dvec2(q.x, q.y) / q.z;
}

glm::dvec3 CardView::to_world(const glm::dvec2& image) const {
  const glm::dvec3 q = glm::inverse(H) * glm::dvec3(image, 1.0);
  return glm::dvec3(q.x / q.z, q.y / q.z, 0.0);
}

CardView locate_card(const Photo& photo, std::optional<double> focal_px, const std::string& what) {
  const CaptureCard& card = capture_card();
  const std::vector<TagSighting> tags = detect_tags(photo);
  CardView view;
  std::vector<const TagSighting*> corners;
  const TagSighting* marker = nullptr;
  for (const TagSighting& t : tags) {
    if (t.id == card.swatch_marker.id) marker = &t;
    for (const CardTag& c : card.corner_tags)
      if (c.id == t.id) corners.push_back(&t);
  }
  if (corners.size() < 2)
    throw CaptureRejection(what + ": the capture card was not found (" + std::to_string(corners.size()) +
                           " of its 4 corner tags seen; keep the whole card in the frame, in focus)");
  // Which detector corner is which corner of the black square: the four cyclic shifts and their
  // mirrors are tried and the one a homography fits best kept, so no corner-order convention of
  // the detector is assumed.
  double best = 1e300;
  for (int mirror = 0; mirror < 2; ++mirror)
    for (int shift = 0; shift < 4; ++shift) {
      std::vector<glm::dvec2> pl, im;
      for (const TagSighting* t : corners) {
        const CardTag* c = nullptr;
        for (const CardTag& ct : card.corner_tags)
          if (ct.id == t->id) c = &ct;
        const auto mm = tag_corners_mm(*c);
        for (int k = 0; k < 4; ++k) {
          const int m = mirror ? (4 - k + shift) % 4 : (k + shift) % 4;
          const glm::dvec3 w = card_to_world(mm[m]);
          pl.emplace_back(w.x, w.y);
          im.push_back(t->corners[k]);
        }
      }
      const glm::dmat3 H = fit_homography(pl, im);
      double err = 0;
      for (size_t i = 0; i < pl.size(); ++i) {
        const glm::dvec3 q = H * glm::dvec3(pl[i], 1.0);
        const glm::dvec2 d = glm::dvec2(q.x, q.y) / q.z - im[i];
        err += glm::dot(d, d);
      }
      if (err < best) {
        best = err;
        view.H = H;
        view.reprojection_rms = std::sqrt(err / pl.size());
      }
    }
  view.corner_tags = static_cast<int>(corners.size());
  if (view.reprojection_rms > 3.0)
    throw CaptureRejection(what + ": the card's tags do not lie on one plane (reprojection " +
                           std::to_string(view.reprojection_rms) + " px): is the card flat?");
  double f = 0;
  if (focal_px) {
    f = *focal_px;
  } else {
    const auto est = focal_from_homography(view.H, photo.width, photo.height);
    f = est ? *est : 1.2 * photo.width;
    view.focal_estimated = true;
  }
  view.camera = pose_from_homography(view.H, f, photo.width, photo.height);

  // The marker's turn: its image axes against those of the corner tags, in the card's plane.
  auto tag_angle = [&](const TagSighting& t) {
    const glm::dvec3 a = view.to_world(t.corners[0]), b = view.to_world(t.corners[1]);
    return std::atan2(b.y - a.y, b.x - a.x);
  };
  if (marker) {
    double sx = 0, sy = 0;
    for (const TagSighting* t : corners) sx += std::cos(tag_angle(*t)), sy += std::sin(tag_angle(*t));
    double turn = tag_angle(*marker) - std::atan2(sy, sx);
    turn = std::remainder(turn, 2 * kPi);
    view.marker_turn = turn;
    glm::dvec3 c(0);
    for (const auto& p : marker->corners) c += view.to_world(p);
    view.marker_centre = c / 4.0;
  }

  // Sharpness: across each corner tag's four outer edges, paper (a cell outside) to ink (a cell in).
  std::vector<double> rises;
  for (const TagSighting* t : corners) {
    const CardTag* c = nullptr;
    for (const CardTag& ct : card.corner_tags)
      if (ct.id == t->id) c = &ct;
    const double h = c->size / 2, cell = c->size / 8;
    const glm::dvec2 dirs[4] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    for (const auto& d : dirs)
      for (double along : {-0.25, 0.25}) {
        const glm::dvec2 side(-d.y, d.x);
        const glm::dvec2 in_mm = c->centre + d * (h - cell) + side * (along * c->size);
        const glm::dvec2 out_mm = c->centre + d * (h + cell * 0.9) + side * (along * c->size);
        rises.push_back(edge_rise(photo, view.to_image(card_to_world(in_mm)), view.to_image(card_to_world(out_mm))));
      }
  }
  std::nth_element(rises.begin(), rises.begin() + rises.size() / 2, rises.end());
  view.edge_width = rises[rises.size() / 2];
  return view;
}

}  // namespace weft
