#pragma once
// Ends and picks per centimetre from the close-up. The weave repeats across the frame, so the 2-D
// spectrum of the pixels' log luminance is a lattice of lines: the reciprocal lattice of the
// weave's repeat. Its points follow from the counts and the weave's rows and shift
// (core/weave_layout.h): the repeat is spanned by T₁ = (rows / p, 0) along the warp and
// T₂ = (shift / p, 1 / e) (one end across, the floats' start moved by `shift` picks), so the
// lattice is m·G₁ + n·G₂ with G₁ = (p / rows, −e·shift / rows), G₂ = (0, e). The counts are those
// whose lattice lies on the spectrum's lines: every point counts, not only the yarns' own lines
// (a plain weave of yarns with no gaps between them shows its ends only on the diagonal lines).
// The scale tag gives the millimetres and roughly which way the warp runs; the fit finds the
// lattice's own direction within 8° of it, so a hand-laid tag a few degrees off costs nothing.
#include <optional>
#include <vector>

#include "capture/closeup_scale.h"

namespace weft {

// The close-up's power spectrum over the largest disc clear of the tag, under a radial Hann
// window, zero-padded to twice the disc: the log of each bin's power over the median of its ring
// (the bins as far from the centre).
struct CloseupSpectrum {
  int n = 0;                     // the transform's side, pixels
  std::vector<float> log_power;  // n rows × (n/2 + 1) columns (the other half is the mirror)
  double px_per_mm = 0;
  glm::dvec2 warp{1.0, 0.0};     // the tag's +x, image direction
  double disc_mm = 0;
  // Bin (kx, ky) of the full n × n spectrum, either half (−k is k for a real image); kx ≥ n/2 + 1
  // after folding is past Nyquist and reads as nothing.
  double log_power_at(int kx, int ky) const;
};

// Nothing when the frame leaves no disc of 64 pixels clear of the tag.
std::optional<CloseupSpectrum> closeup_spectrum(const std::vector<double>& signal, const std::vector<bool>& use,
                                                int width, int height, const CloseupScale& scale);

struct ThreadCounts {
  double ends_per_cm = 0, picks_per_cm = 0;
  double angle = 0;        // the lattice's warp off the tag's +x, radians
  // The lattice's warp in the image: the tag's +x `tag_warp` turned by `angle`.
  glm::dvec2 warp(glm::dvec2 tag_warp) const;
  // The share of the strong lines' weight near the lattice (to 1.5 lines), less the share a lattice
  // of its density would have near it by chance.
  double score = 0;
  int points = 0;          // strong lines found (the lowest 16)
  int fitted_lines = 0;    // those within a line of the fitted lattice, which set the counts
  double fitted_share = 0; // their share of the lines' weight, less chance's (as `score`)
  double resolution_per_cm = 0;  // one line's width in the spectrum: 1 / the disc's diameter
  // Most of the strong lines near the lattice the search found, and most of them (by weight) within
  // a line of the one fitted to them: a wrong lattice that a coarse step let explain the lines
  // leaves a third of them off once fitted.
  bool resolved() const { return fitted_lines >= 3 && score >= kResolvedScore && fitted_share >= kResolvedFit; }
  // Short of that, still worth registering the close-up to: the registration then confirms the
  // lattice or not (a plain weave of two unequal counts leaves a third of its strong lines on
  // harmonics the coarse search does not fit).
  bool candidate() const { return fitted_lines >= 3 && score >= kCandidateScore && fitted_share >= kCandidateFit; }
  static constexpr double kResolvedScore = 0.8, kResolvedFit = 0.8;
  static constexpr double kCandidateScore = 0.6, kCandidateFit = 0.6;
};

// The counts (each 3–200 per cm, at least 5 repeats of the disc and 4 pixels a yarn, ends and picks
// within 3 : 1) of a weave of `rows` and `shift` (or its mirror, −shift): the coarsest lattice on
// which nearly all of the spectrum's lowest strong lines lie, its basis then fitted to them by
// weighted least squares.
ThreadCounts weave_counts(const CloseupSpectrum& spectrum, int rows, int shift);

}  // namespace weft
