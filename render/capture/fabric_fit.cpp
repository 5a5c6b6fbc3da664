#include "capture/fabric_fit.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include <Eigen/Dense>
#include <unsupported/Eigen/NonLinearOptimization>
#include <unsupported/Eigen/NumericalDiff>

#include "capture/fit_uncertainty.h"
#include "capture/swatch_frame.h"
#include "core/cloth_bsdf.h"
#include "core/fresnel.h"

namespace weft {

namespace {

// One tangent sample of one thread under one light for one observation: θ_h and the factors that
// multiply N(θ_h; γ_s) (surface) and the volume lobe (per unit albedo), W·cos θ_i / (cos²θ_d·N_j)
// included.
struct Term {
  float theta_h, surface, volume;
};

// What a preset's weave fixes of the model at every observation.
struct Geometry {
  int observations = 0, lights = 0;
  std::array<int, 2> samples{};
  std::array<std::vector<Term>, 2> terms;      // [j][(o·L + l)·N_j + k]
  std::array<std::vector<glm::dvec3>, 2> flat;  // [j][o]: flat_sums
};

// Σ_l P_l Σ_k (volume factor) for thread j at every observation: what k_d weighs.
std::vector<glm::dvec3> flat_sums(const Geometry& g, const std::vector<FitLight>& lights, int j) {
  std::vector<glm::dvec3> out(g.observations, glm::dvec3(0));
  const int n = g.samples[j];
  for (int o = 0; o < g.observations; ++o)
    for (int l = 0; l < g.lights; ++l) {
      const Term* t = &g.terms[j][(static_cast<size_t>(o) * g.lights + l) * n];
      double s = 0;
      for (int k = 0; k < n; ++k) s += t[k].volume;
      out[o] += s * lights[l].power;
    }
  return out;
}

Geometry precompute(const Fabric& fabric, const std::vector<SwatchObservation>& obs, const std::vector<FitLight>& lights,
                    int tangent_samples) {
  Geometry g;
  g.observations = static_cast<int>(obs.size());
  g.lights = static_cast<int>(lights.size());
  std::array<std::vector<double>, 2> tilts;
  for (int j = 0; j < 2; ++j) {
    tilts[j] = fabric.threads[j].curve.sample_tilts(tangent_samples);
    g.samples[j] = static_cast<int>(tilts[j].size());
    g.terms[j].assign(static_cast<size_t>(g.observations) * g.lights * g.samples[j], Term{0, 0, 0});
  }
#pragma omp parallel for schedule(dynamic)
  for (int o = 0; o < g.observations; ++o) {
    const double t = obs[o].turn;
    const SurfaceFrame frame = swatch_frame(t);
    const glm::dvec3 wo = obs[o].wo;
    std::array<std::vector<ThreadFrame>, 2> frames;
    for (int j = 0; j < 2; ++j)
      for (double a : tilts[j]) frames[j].push_back(thread_frame(frame, j, a));
    std::array<std::vector<FiberAngles>, 2> in, out;
    std::array<std::vector<double>, 2> proj;
    for (int l = 0; l < g.lights; ++l) {
      const glm::dvec3 wi = lights[l].direction;
      if (wi.z <= 0 || wo.z <= 0) continue;
      double q = (1.0 - fabric.threads[0].coverage - fabric.threads[1].coverage) * wo.z;
      for (int j = 0; j < 2; ++j) {
        in[j].resize(g.samples[j]);
        out[j].resize(g.samples[j]);
        proj[j].resize(g.samples[j]);
        double sum = 0;
        for (int k = 0; k < g.samples[j]; ++k) {
          in[j][k] = fiber_angles(frames[j][k], wi);
          out[j][k] = fiber_angles(frames[j][k], wo);
          proj[j][k] = projection(in[j][k], out[j][k]);
          sum += proj[j][k];
        }
        q += fabric.threads[j].coverage * sum / g.samples[j];
      }
      if (q <= kQFloor) continue;
      for (int j = 0; j < 2; ++j) {
        const ThreadParams& p = fabric.threads[j];
        for (int k = 0; k < g.samples[j]; ++k) {
          if (proj[j][k] <= 0) continue;
          const double w = p.coverage * masking(in[j][k], out[j][k]) * proj[j][k] / q;
          if (w <= 0) continue;
          const double theta_d = (in[j][k].theta - out[j][k].theta) / 2, theta_h = (in[j][k].theta + out[j][k].theta) / 2;
          const double cos_half_phi = std::cos(wrap_angle(in[j][k].phi - out[j][k].phi) / 2);
          const double factor = w * std::cos(in[j][k].theta) /
                                (std::max(std::cos(theta_d) * std::cos(theta_d), kModelDenominatorFloor) * g.samples[j]);
          const double fr = fresnel_dielectric(p.eta, std::cos(theta_d) * cos_half_phi);
          const double denom = std::max(std::cos(in[j][k].theta) + std::cos(out[j][k].theta), kModelDenominatorFloor);
          Term& term = g.terms[j][(static_cast<size_t>(o) * g.lights + l) * g.samples[j] + k];
          term.theta_h = static_cast<float>(theta_h);
          term.surface = static_cast<float>(fr * cos_half_phi * factor);
          term.volume = static_cast<float>((1 - fr) * (1 - fr) / denom * factor);
        }
      }
    }
  }
  for (int j = 0; j < 2; ++j) g.flat[j] = flat_sums(g, lights, j);
  return g;
}

// Σ_l P_l Σ_k (surface or volume factor)·N(θ_h; γ) for thread j at every observation.
std::vector<glm::dvec3> lobe_sums(const Geometry& g, const std::vector<FitLight>& lights, int j, bool volume, double gamma) {
  std::vector<glm::dvec3> out(g.observations, glm::dvec3(0));
  const double inv = 1.0 / (gamma * std::sqrt(2.0 * 3.14159265358979323846)), c = -0.5 / (gamma * gamma);
  const int n = g.samples[j];
#pragma omp parallel for schedule(static)
  for (int o = 0; o < g.observations; ++o) {
    glm::dvec3 sum(0);
    for (int l = 0; l < g.lights; ++l) {
      const Term* t = &g.terms[j][(static_cast<size_t>(o) * g.lights + l) * n];
      double s = 0;
      for (int k = 0; k < n; ++k) {
        const double f = volume ? t[k].volume : t[k].surface;
        if (f != 0) s += f * std::exp(c * t[k].theta_h * t[k].theta_h);
      }
      sum += s * lights[l].power;
    }
    out[o] = sum * inv;
  }
  return out;
}

struct Bounds {
  double lo, hi;
};
// Per thread: A_r, A_g, A_b, k_d, γ_s, γ_v. The presets span A ≤ 0.6, k_d 0.1–0.7, γ_s 2.5–30°,
// γ_v 5–60°; the bounds leave room on every side.
constexpr std::array<Bounds, 6> kBounds{{{0.0, 1.0}, {0.0, 1.0}, {0.0, 1.0}, {0.01, 0.95},
                                          {0.0175, 0.785}, {0.035, 1.571}}};
constexpr int kParams = 12;

double logistic(double z) { return 1.0 / (1.0 + std::exp(-z)); }
double to_value(int i, double z) { const Bounds& b = kBounds[i % 6]; return b.lo + (b.hi - b.lo) * logistic(z); }

// Thread j's parameters at z.
struct ThreadValues {
  glm::dvec3 A;
  double kd, gamma_s, gamma_v;
};
ThreadValues thread_values(const Eigen::VectorXd& z, int j) {
  const int k = 6 * j;
  return {glm::dvec3(to_value(k, z[k]), to_value(k + 1, z[k + 1]), to_value(k + 2, z[k + 2])), to_value(k + 3, z[k + 3]),
          to_value(k + 4, z[k + 4]), to_value(k + 5, z[k + 5])};
}
double to_z(int i, double v) {
  const Bounds& b = kBounds[i % 6];
  const double f = std::clamp((v - b.lo) / (b.hi - b.lo), 0.02, 0.98);
  return std::log(f / (1 - f));
}

// A/(A_r + A_g + A_b): the colour without its lightness.
glm::dvec3 chromaticity(const glm::dvec3& a) { return a / std::max(a.r + a.g + a.b, 1e-6); }

// The family's preset with the threads of z.
Fabric fitted_fabric(const Fabric& preset, const Eigen::VectorXd& z) {
  Fabric f = preset;
  for (int j = 0; j < 2; ++j) {
    ThreadParams& t = f.threads[j];
    const ThreadValues v = thread_values(z, j);
    t.albedo = v.A;
    t.kd = v.kd;
    t.gamma_s = v.gamma_s;
    t.gamma_v = v.gamma_v;
  }
  return f;
}

constexpr double kHuber = 2.0;
constexpr double kPriorWeight = 0.5;
constexpr double kBroadStart[2] = {20.0, 40.0};  // γ_s, γ_v in degrees: the second start's lobes
constexpr double kSecondStartWithin = 4.0;        // × the lowest cost after the first starts
// 1σ of a level error common to every cell, per channel (the response's scale, the ball's
// calibration): taken as the 2 % a cell's residual unit allows.
constexpr double kLevelSigma = 0.02;
// 1σ of the lighting's shape as the ball gives it: each light's power off by this fraction of its
// height above the lights' mean (and of its direction's x and y), common to every photo.
constexpr double kShapeSigma = 0.1;
// 1σ of the close-up's log ratio of the threads' means, per channel: the ball's lighting against
// the room's (the ratio depends on it through each thread's highlight), the k-means' split, JPEG.
constexpr double kCloseupSigma = 0.05;
// ... when the threads' means come from the close-up registered to the weave: thousands of pixels
// each, the threads told apart by where they lie; what is left is the lighting.
constexpr double kRegisteredSigma = 0.02;
// 1σ of the close-up's swatch level, relative, per channel (floored at a quarter of its mean): the
// tag's paper against the card's, the ball's light from straight above against the room's.
constexpr double kCloseupLevelSigma = 0.03;
// The registered albedos' chromaticities (L1) within which they agree with clusters that show one
// hue: same-dye threads read 0.01–0.15 apart (velvet's near-black pile the most), an orange and a
// blue 0.5.
constexpr double kRegisteredOneHue = 0.2;
// The share of the folded tile's variance above which a registration's means carry the threads'
// lightness: the sweep's satins, crêpe and shot silks 0.96–0.99, velvet 0.66.
constexpr double kRegisteredClose = 0.9;
// 1σ of the difference of the chromaticities A/(A_r + A_g + A_b) of two threads a close-up shows
// as one hue, and of their lightness A_r + A_g + A_b (relative) when it shows one colour.
constexpr double kOneColourSigma = 0.02;
constexpr double kOneLightnessSigma = 0.05;

struct Residuals {
  using Scalar = double;
  enum { InputsAtCompileTime = Eigen::Dynamic, ValuesAtCompileTime = Eigen::Dynamic };
  using InputType = Eigen::VectorXd;
  using ValueType = Eigen::VectorXd;
  using JacobianType = Eigen::MatrixXd;

  const Geometry* g;
  const std::vector<FitLight>* lights;
  const std::vector<SwatchObservation>* obs;  // the photos' cells; a close-up is g's last observation
  std::vector<glm::dvec3> scale;  // per observation: the residual's unit
  bool robust = true;
  // The close-up's cluster means, the warp's first, and the threads' coverages a_j.
  std::optional<std::array<glm::dvec3, 2>> closeup;
  double closeup_sigma = kCloseupSigma;
  std::optional<glm::dvec3> level;  // the close-up's swatch level straight above
  bool one_colour = false;     // the threads' chromaticities tied instead
  bool one_lightness = false;  // ... and their lightness
  std::array<double, 2> coverage{1, 1};
  // The family's own k_d, γ_s and γ_v as a weak prior (z units): a few turns of a flat swatch
  // leave the threads' lobes partly interchangeable, and the preset is the likeliest cloth.
  Eigen::VectorXd prior;
  // The lobe sums for the last γ each lobe was asked at: a Jacobian column moves one of them.
  struct Cache {
    double gamma = -1;
    std::vector<glm::dvec3> sums;
  };
  mutable std::array<Cache, 4> cache;

  int inputs() const { return kParams; }
  int cells() const { return static_cast<int>(obs->size()); }
  int values() const {
    return 3 * cells() + 6 + (closeup ? 3 : 0) + (level ? 3 : 0) + (one_colour ? 3 : 0) + (one_lightness ? 1 : 0);
  }

  const std::vector<glm::dvec3>& lobe(int j, bool volume, double gamma) const {
    Cache& c = cache[2 * j + volume];
    if (c.gamma != gamma) {
      c.sums = lobe_sums(*g, *lights, j, volume, gamma);
      c.gamma = gamma;
    }
    return c.sums;
  }

  // A thread's share of the swatch's radiance from its lobe sums: the surface's, the volume's and
  // the flat term k_d weighs (design §2's f_rs + f_rv, summed over the lights).
  static glm::dvec3 thread_radiance(const ThreadValues& t, const glm::dvec3& surface, const glm::dvec3& volume, const glm::dvec3& flat) {
    return surface + t.A * ((1 - t.kd) * volume + t.kd * flat);
  }

  // Thread j's share of the swatch's radiance at observation o of g.
  glm::dvec3 thread_at(const ThreadValues& t, int j, int o) const {
    return thread_radiance(t, lobe(j, false, t.gamma_s)[o], lobe(j, true, t.gamma_v)[o], g->flat[j][o]);
  }

  // The photos' cells at z with each light's power times weight[l]: the model is linear in the
  // lights, so this is how a change in the lighting's shape moves them.
  std::vector<glm::dvec3> cells_with_weights(const Eigen::VectorXd& z, const std::vector<double>& weight) const {
    std::vector<FitLight> weighted = *lights;
    for (size_t l = 0; l < weighted.size(); ++l) weighted[l].power *= weight[l];
    std::vector<glm::dvec3> out(cells(), glm::dvec3(0));
    for (int j = 0; j < 2; ++j) {
      const ThreadValues t = thread_values(z, j);
      const auto surface = lobe_sums(*g, weighted, j, false, t.gamma_s), volume = lobe_sums(*g, weighted, j, true, t.gamma_v);
      const auto flat = flat_sums(*g, weighted, j);
      for (int o = 0; o < cells(); ++o) out[o] += thread_radiance(t, surface[o], volume[o], flat[o]);
    }
    return out;
  }

  std::vector<glm::dvec3> model(const Eigen::VectorXd& z) const {
    const ThreadValues warp = thread_values(z, 0), weft = thread_values(z, 1);
    std::vector<glm::dvec3> out(g->observations);
    for (int o = 0; o < g->observations; ++o) out[o] = thread_at(warp, 0, o) + thread_at(weft, 1, o);
    return out;
  }

  // Warp ÷ weft resolved mean radiance straight above (the close-up's view, g's last observation).
  glm::dvec3 closeup_ratio(const Eigen::VectorXd& z) const {
    const int o = g->observations - 1;
    const glm::dvec3 warp = thread_at(thread_values(z, 0), 0, o) / coverage[0];
    const glm::dvec3 weft = thread_at(thread_values(z, 1), 1, o) / coverage[1];
    return glm::max(warp, glm::dvec3(1e-12)) / glm::max(weft, glm::dvec3(1e-12));
  }

  // The swatch's mean radiance straight above.
  glm::dvec3 closeup_level(const Eigen::VectorXd& z) const {
    const int o = g->observations - 1;
    return glm::max(thread_at(thread_values(z, 0), 0, o) + thread_at(thread_values(z, 1), 1, o), glm::dvec3(1e-12));
  }

  // How far a warp ÷ weft ratio misses the measured one, per channel (log).
  static glm::dvec3 closeup_miss(const glm::dvec3& fitted, const std::array<glm::dvec3, 2>& measured) {
    return glm::log(fitted) - glm::log(measured[0] / measured[1]);
  }
  // The robust cost of the photos' cells alone.
  double cells_cost(const Eigen::VectorXd& z) const {
    Eigen::VectorXd f(values());
    (*this)(z, f);
    return f.head(3 * cells()).squaredNorm();
  }

  int operator()(const Eigen::VectorXd& z, Eigen::VectorXd& f) const {
    const auto m = model(z);
    for (int o = 0; o < cells(); ++o)
      for (int c = 0; c < 3; ++c) {
        double r = (m[o][c] - (*obs)[o].value[c]) / scale[o][c];
        // Huber's loss as a residual: its square is the loss.
        if (robust && std::abs(r) > kHuber) r = std::copysign(std::sqrt(2 * kHuber * std::abs(r) - kHuber * kHuber), r);
        f[3 * o + c] = r;
      }
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i) f[3 * cells() + 3 * j + i] = kPriorWeight * (z[6 * j + 3 + i] - prior[6 * j + 3 + i]);
    int k = 3 * cells() + 6;
    if (closeup) {
      const glm::dvec3 d = closeup_miss(closeup_ratio(z), *closeup) / closeup_sigma;
      for (int c = 0; c < 3; ++c) f[k++] = d[c];
    }
    if (level) {
      // Floored as the photos' cells are: a near-black channel reads JPEG and noise, not the cloth.
      const double floor = 0.25 * (level->r + level->g + level->b) / 3;
      const glm::dvec3 d = (closeup_level(z) - *level) / (kCloseupLevelSigma * glm::max(*level, glm::dvec3(floor)));
      for (int c = 0; c < 3; ++c) f[k++] = d[c];
    }
    if (one_colour) {
      const glm::dvec3 a = thread_values(z, 0).A, b = thread_values(z, 1).A;
      const glm::dvec3 d = chromaticity(a) - chromaticity(b);
      for (int c = 0; c < 3; ++c) f[k++] = d[c] / kOneColourSigma;
      if (one_lightness) {
        const double la = a.r + a.g + a.b, lb = b.r + b.g + b.b;
        f[k++] = (la - lb) / (kOneLightnessSigma * std::max(0.5 * (la + lb), 1e-6));
      }
    }
    return 0;
  }
};

// One Levenberg–Marquardt fit of a family from a start: where it ended, its cost.
struct Run {
  double cost = std::numeric_limits<double>::infinity();
  Eigen::VectorXd z;
  int iterations = 0;
};

void minimize(const Residuals& r, Run& run) {
  Eigen::NumericalDiff<Residuals> diff(r);
  Eigen::LevenbergMarquardt<Eigen::NumericalDiff<Residuals>> lm(diff);
  lm.parameters.maxfev = 60 * (kParams + 1);
  lm.parameters.xtol = 1e-8;
  lm.minimize(run.z);
  run.iterations += static_cast<int>(lm.iter);
  Eigen::VectorXd f(r.values());
  r(run.z, f);
  run.cost = f.squaredNorm();
}

// The chosen family fitted again with the close-up (fabric_fit.h): `run` and `r` take it when it is
// used, and are left as they were when it is not.
CloseupFit refit_with_closeup(Residuals& r, Run& run, const CloseupObservation& closeup, const Fabric& fitted) {
  CloseupFit fit;
  const glm::dvec3 ratio = r.closeup_ratio(run.z);
  const double expected = r.coverage[0] / (r.coverage[0] + r.coverage[1]);
  std::array<glm::dvec3, 2> measured{};
  std::optional<CloseupObservation::Registered> registered;
  if (closeup.registered) registered = closeup.registered(fitted);
  fit.registered = registered.has_value();
  // One hue when the split on colour alone does not separate: a split by lightness then cuts one
  // colour's shading (or two lightnesses of one dye), which no ratio of two clusters describes;
  // one colour when neither separates. When the close-up registered, one hue only if the albedos
  // it read agree (fine yarns blurred into each other, or a satin's white highlights, leave no
  // valley between two hues: an orange warp over a blue weft read as one colour), and one
  // lightness only where the weave's model explains the close-up loosely: a close registration's
  // means carry the threads' lightness (crêpe's one dye at 0.12 and 0.16), a loose one's do not
  // (velvet's pile, 66 % explained, came back ΔE 17 off without the tie).
  fit.one_colour = !closeup.splits.empty();
  for (const CloseupSplit& split : closeup.splits) fit.one_colour = fit.one_colour && (split.lightness || !split.separated());
  if (registered) {
    // The albedos where it read them; else the means (the surface's white in them draws two hues
    // together: a looser test than the albedos', which only the clusters' own one hue gates).
    const auto& hue = registered->albedo ? *registered->albedo : registered->mean;
    const glm::dvec3 d = glm::abs(chromaticity(hue[0]) - chromaticity(hue[1]));
    fit.one_colour = fit.one_colour && d.r + d.g + d.b < kRegisteredOneHue;
  }
  const bool none_separates =
      std::none_of(closeup.splits.begin(), closeup.splits.end(), [](const CloseupSplit& s) { return s.separated(); });
  fit.one_lightness = fit.one_colour && none_separates && (!registered || registered->explained < kRegisteredClose);
  double best_share_error = 1;
  if (registered) measured = registered->mean;
  for (size_t k = 0; k < closeup.splits.size() && !fit.one_colour && !fit.registered; ++k) {
    const CloseupSplit& split = closeup.splits[k];
    if (!split.separated()) continue;
    const auto& m = split.mean;
    int warp = std::abs(split.share[1] - expected) < std::abs(split.share[0] - expected);
    if (std::abs(expected - 0.5) < kCloseupShare / 2) {
      // Even coverages: the shares cannot tell; the family's fit without the close-up can.
      const double as_is = glm::length(Residuals::closeup_miss(ratio, {m[0], m[1]}));
      warp = glm::length(Residuals::closeup_miss(ratio, {m[1], m[0]})) < as_is;
    }
    const double share_error = std::abs(split.share[warp] - expected);
    if (share_error <= kCloseupShare && share_error < best_share_error) {
      best_share_error = share_error;
      fit.split = static_cast<int>(k);
      fit.warp_cluster = warp;
      fit.warp_share = split.share[warp];
      measured = {m[warp], m[1 - warp]};
    }
  }
  r.one_colour = fit.one_colour;
  r.one_lightness = fit.one_lightness;
  if (!fit.one_colour && !fit.registered && fit.split < 0) {
    char why[200];
    const CloseupSplit& s = closeup.splits.front();
    std::snprintf(why, sizeof why, "no split's clusters cover what the family's threads do (%.0f %% and %.0f %% against %.0f %%)",
                  100 * std::max(s.share[0], s.share[1]), 100 * std::min(s.share[0], s.share[1]), 100 * std::max(expected, 1 - expected));
    fit.rejected = why;
    fit.fitted_ratio = ratio;
    return fit;
  }
  if (fit.registered || fit.split >= 0) {
    fit.measured_ratio = measured[0] / measured[1];
    r.closeup = measured;
    r.closeup_sigma = fit.registered ? kRegisteredSigma : kCloseupSigma;
  }
  if (closeup.level && glm::all(glm::greaterThan(*closeup.level, glm::dvec3(0)))) {
    r.level = closeup.level;
    fit.measured_level = closeup.level;
  }
  const double cost_without = r.cells_cost(run.z);
  // Whether a refit holds the close-up: what it misses of the measured ratio (log, worst
  // channel) and the photos' cost it costs.
  auto verdict = [&](const Run& with) {
    std::string why;
    char line[160];
    double worst = 0;
    if (r.closeup) {
      const glm::dvec3 miss = glm::abs(Residuals::closeup_miss(r.closeup_ratio(with.z), measured));
      worst = std::max({miss.r, miss.g, miss.b});
    }
    const double cost_with = r.cells_cost(with.z);
    const double growth = fit.registered ? kRegisteredCostGrowth : kCloseupCostGrowth;
    if (worst > kCloseupMisses) {
      std::snprintf(line, sizeof line, "the fitted threads miss its warp ÷ weft ratio by %.0f %% in a channel", 100 * (std::exp(worst) - 1));
      why = line;
    } else if (cost_with > growth * cost_without) {
      std::snprintf(line, sizeof line, "matching it costs the photos' fit %.1f× its cost without", cost_with / cost_without);
      why = line;
    }
    return why;
  };
  Run with = run;
  minimize(r, with);
  std::string why = verdict(with);
  if (registered && registered->albedo && !why.empty()) {
    // Again from the threads' albedos the registration read under the photos' lobes: the photos'
    // optimum can lie in a valley the close-up's ratio does not lead out of.
    Run again = run;
    for (int j = 0; j < 2; ++j)
      for (int c = 0; c < 3; ++c) again.z[6 * j + c] = to_z(c, (*registered->albedo)[j][c]);
    minimize(r, again);
    if (const std::string again_why = verdict(again); again_why.empty() || again.cost < with.cost) {
      with = std::move(again);
      why = again_why;
    }
  }
  fit.fitted_ratio = r.closeup_ratio(with.z);
  if (r.level) fit.fitted_level = r.closeup_level(with.z);
  fit.used = why.empty();
  fit.rejected = why;
  if (fit.used) {
    run = with;
  } else {
    r.closeup.reset();
    r.level.reset();
    r.one_colour = r.one_lightness = false;
    fit.fitted_ratio = ratio;
  }
  return fit;
}

}  // namespace

FabricFit fit_fabric(const std::vector<SwatchObservation>& observations, const std::vector<FitLight>& lights,
                     const std::vector<Fabric>& presets, const FabricFitOptions& options,
                     const std::optional<CloseupObservation>& closeup) {
  if (observations.empty() || lights.empty() || presets.empty())
    throw std::invalid_argument("fit_fabric: needs observations, lights and presets");
  glm::dvec3 mean(0);
  for (const auto& o : observations) mean += o.value;
  mean /= static_cast<double>(observations.size());
  const double level = (mean.r + mean.g + mean.b) / 3;
  // One family from one start: the preset's own lobes, or broad ones (a fabric of the family whose
  // lobes are far wider than its preset's lies beyond the preset start's local minimum).
  auto residuals = [&](const Geometry& g, const Fabric& preset) {
    Residuals r;
    r.g = &g;
    r.lights = &lights;
    r.obs = &observations;
    r.coverage = {preset.threads[0].coverage, preset.threads[1].coverage};
    // The residual's unit: 2 % of the value (JPEG, noise, the response's fit), floored at 0.5 % of the
    // swatch's mean so a black channel does not count for more than it can be measured.
    for (const auto& o : observations) r.scale.push_back(0.02 * glm::max(o.value, glm::dvec3(0.25 * level)));
    r.prior = Eigen::VectorXd(kParams);
    for (int j = 0; j < 2; ++j) {
      const ThreadParams& t = preset.threads[j];
      const double start[6] = {t.albedo.r, t.albedo.g, t.albedo.b, t.kd, t.gamma_s, t.gamma_v};
      for (int i = 0; i < 6; ++i) r.prior[6 * j + i] = to_z(i, start[i]);
    }
    return r;
  };
  // Each family's geometry, once: the photos' cells, then the close-up's view (straight above).
  std::vector<SwatchObservation> seen = observations;
  if (closeup) seen.push_back({glm::dvec3(0), glm::dvec3(0, 0, 1), closeup->turn, -1});
  std::vector<Geometry> geometries(presets.size());
  auto run_family = [&](size_t p, bool broad) {
    const Fabric& preset = presets[p];
    if (geometries[p].observations == 0) geometries[p] = precompute(preset, seen, lights, options.tangent_samples);
    const Residuals r = residuals(geometries[p], preset);
    Run run;
    run.z = r.prior;
    if (broad)
      for (int j = 0; j < 2; ++j) {
        run.z[6 * j + 4] = to_z(4, glm::radians(kBroadStart[0]));
        run.z[6 * j + 5] = to_z(5, glm::radians(kBroadStart[1]));
      }
    minimize(r, run);
    return run;
  };
  // Every family from its preset, then again from broad lobes for those within kSecondStartWithin
  // of the lowest cost (the others cannot win).
  std::vector<Run> runs;
  for (size_t p = 0; p < presets.size(); ++p) {
    runs.push_back(run_family(p, false));
    if (options.progress) options.progress(0.55 * static_cast<double>(p + 1) / presets.size());
  }
  double lowest = std::numeric_limits<double>::infinity();
  for (const Run& run : runs) lowest = std::min(lowest, run.cost);
  for (size_t p = 0; p < presets.size(); ++p) {
    if (runs[p].cost <= kSecondStartWithin * lowest)
      if (Run again = run_family(p, true); again.cost < runs[p].cost) runs[p] = std::move(again);
    if (options.progress) options.progress(0.55 + 0.25 * static_cast<double>(p + 1) / presets.size());
  }
  FabricFit best;
  size_t chosen = 0;
  for (size_t p = 0; p < presets.size(); ++p) {
    best.family_costs.emplace_back(presets[p].name, runs[p].cost);
    if (runs[p].cost < runs[chosen].cost) chosen = p;
  }
  {
    const Fabric& preset = presets[chosen];
    Run& run = runs[chosen];
    const double cost = run.cost;  // what the family was chosen by
    Geometry fine;
    if (options.final_tangent_samples > options.tangent_samples) {
      fine = precompute(preset, seen, lights, options.final_tangent_samples);
      minimize(residuals(fine, preset), run);
      if (options.progress) options.progress(0.9);
    }
    Residuals r = residuals(fine.observations > 0 ? fine : geometries[chosen], preset);
    if (closeup) best.closeup = refit_with_closeup(r, run, *closeup, fitted_fabric(preset, run.z));
    if (options.progress) options.progress(1.0);
    const Eigen::VectorXd& z = run.z;
    Eigen::NumericalDiff<Residuals> diff(r);
    best.cost = cost;
    best.preset = preset.name;
    best.iterations = run.iterations;
    best.fabric = fitted_fabric(preset, z);
    const auto m = r.model(z);
    double rel = 0;
    for (int o = 0; o < r.cells(); ++o)
      for (int c = 0; c < 3; ++c) {
        const double d = (m[o][c] - observations[o].value[c]) / std::max(observations[o].value[c], 0.05 * level);
        rel += d * d;
      }
    best.rms_relative = std::sqrt(rel / (3.0 * r.cells()));
    // 1σ (fit_uncertainty.h), carried through the logistic maps.
    r.robust = false;
    Eigen::MatrixXd J(r.values(), kParams);
    diff.df(z, J);
    Eigen::VectorXd f2(r.values());
    r(z, f2);
    std::array<Eigen::VectorXd, 3> level;
    for (int c = 0; c < 3; ++c) {
      level[c] = Eigen::VectorXd::Zero(r.values());
      for (int o = 0; o < r.cells(); ++o) level[c][3 * o + c] = -observations[o].value[c] / r.scale[o][c];
    }
    // The lighting's shape, which the residuals cannot show either: the ball's reading of how
    // much light comes from high against low, and from either side (fit_uncertainty.h).
    std::array<Eigen::VectorXd, 3> shape;
    {
      double power = 0, height = 0;
      for (const FitLight& l : lights) {
        const double p = l.power.r + l.power.g + l.power.b;
        power += p;
        height += p * l.direction.z;
      }
      height /= std::max(power, 1e-12);
      for (int a = 0; a < 3; ++a) {
        std::vector<double> weight(lights.size());
        for (size_t l = 0; l < lights.size(); ++l) weight[l] = a == 0 ? lights[l].direction.z - height : lights[l].direction[a - 1];
        const std::vector<glm::dvec3> moved = r.cells_with_weights(z, weight);
        shape[a] = Eigen::VectorXd::Zero(r.values());
        for (int o = 0; o < r.cells(); ++o)
          for (int c = 0; c < 3; ++c) shape[a][3 * o + c] = moved[o][c] / r.scale[o][c];
      }
    }
    const Eigen::MatrixXd cov = fit_covariance(J, f2, {{{level, kLevelSigma}, {shape, kShapeSigma}}});
    for (int j = 0; j < 2; ++j) {
      double sd[6];
      for (int i = 0; i < 6; ++i) {
        const int k = 6 * j + i;
        const double s = logistic(z[k]);
        sd[i] = std::sqrt(std::max(cov(k, k), 0.0)) * (kBounds[i].hi - kBounds[i].lo) * s * (1 - s);
      }
      best.sigma[j] = ThreadUncertainty{{sd[0], sd[1], sd[2]}, sd[3], sd[4], sd[5]};
    }
  }
  return best;
}

glm::dvec3 swatch_radiance(const Fabric& fabric, double turn, const glm::dvec3& wo, const std::vector<FitLight>& lights,
                           int tangent_samples) {
  const ClothBsdf bsdf(fabric, tangent_samples);
  ClothBsdf::Point point = bsdf.at(swatch_frame(turn));
  glm::dvec3 sum(0);
  for (const FitLight& l : lights) sum += l.power * point.integrand(l.direction, wo);
  return sum;
}

}  // namespace weft
