#pragma once
// `weft capture DIR`: the whole fit of a capture folder. Per photo: the card (card_detection.h)
// and its grey patches and paper (card_samples.h); the response, fitted across every photo
// (response_calibration.h); per photo again, the swatch's cells and the mirror ball read through
// it; then the lighting from every ball (capture_lighting.h), the close-up's thread clusters when
// the folder has one (closeup_shot.h), and the fabric (fabric_fit.h): for the family the photos
// choose, the close-up's lattice (thread_counts.h) and its registration to that weave
// (closeup_registration.h), whose threads' means the family's refit then holds.
// Unusable input is a CaptureRejection: the card not found, the swatch marker missing, a blurred
// or saturated photo, fewer than three photos or swatch turns.
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "capture/capture_lighting.h"
#include "capture/closeup_registration.h"
#include "capture/closeup_shot.h"
#include "capture/fabric_fit.h"
#include "capture/response_calibration.h"

namespace weft {

struct CapturedPhoto {
  std::string file;
  double turn = 0;            // the swatch's warp angle, radians
  int corner_tags = 0;
  double reprojection_px = 0;
  double edge_width_px = 0;
  bool focal_estimated = false;
  ResponseFit response;
  int brackets = 0;           // darker exposures of the ball beside it
  double ball_clipped = 0;    // the ball's pixels clipped in every exposure
  int cells = 0;
  glm::dvec3 camera_centre{0.0};
  // The rectified swatch, kPanel × kPanel over ±30 mm around the window's centre (world axes,
  // +Y up): the photo's relative values, and whether the marker covers the texel.
  std::vector<glm::dvec3> panel;
  std::vector<bool> panel_marker;
};

inline constexpr int kPanel = 64;

struct CaptureFitOptions {
  double max_edge_width_px = 4.0;   // blurrier photos are rejected
  double max_saturated = 0.02;      // share of the swatch's pixels with a clipped channel
  std::function<std::function<void(double)>(const std::string&)> open_progress;  // a bar per stage
};

struct CaptureFitResult {
  std::vector<CapturedPhoto> photos;
  CaptureLighting lighting;
  std::vector<SwatchObservation> observations;
  std::string closeup_file;                // empty without a close-up
  std::optional<CloseupClusters> closeup;
  // The ends and picks the close-up's spectrum gives for the fitted family's weave, when it holds
  // the scale tag; the fabric takes them when they are resolved.
  std::optional<ThreadCounts> thread_counts;
  std::optional<CloseupRegistration> registration;  // where the counts are a candidate lattice
  FabricFit fit;
  double seconds = 0;
  // Whether the fabric took the counts: the spectrum resolved them, or a candidate lattice the
  // close-up registered to.
  bool counts_resolved() const {
    return thread_counts && (thread_counts->resolved() || (thread_counts->candidate() && registration && registration->registered));
  }
};

// Fits the capture in `dir` with the presets of `presets_dir` as weave families.
CaptureFitResult fit_capture(const std::filesystem::path& dir, const std::filesystem::path& presets_dir,
                             const CaptureFitOptions& options = {});

}  // namespace weft
