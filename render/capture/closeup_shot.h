#pragma once
// The close-up: the swatch from straight above, close enough that each thread spans several
// pixels (a macro lens, or a phone a few centimetres away), shot right after the last photo
// without moving the swatch, at the photos' white balance. The turned photos see the fabric's
// average over many repeats, where a thread that covers a tenth of the swatch moves the colour by
// a tenth of its own; the close-up sees each thread where it lies. Its two colour clusters give
// the ratio of the threads' mean radiances, channel by channel: the exposure and the white
// balance cancel in it, and most of the lighting's error, so it pins a sparse thread's colour to
// the dominant one's (fabric_fit.h). Means, not the spread of the pixels: a glossy float's
// highlight is a few degrees of tilt wide, and only its integral is robust to how the fit samples
// the tilts and the lights.
#include <array>
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "capture/closeup_scale.h"
#include "capture/photo_files.h"
#include "capture/response_calibration.h"
#include "capture/thread_counts.h"

namespace weft {

// One split of the thread pixels into two clusters.
struct CloseupSplit {
  bool lightness = true;             // k-means on log chromaticity and lightness, or chromaticity only
  std::array<glm::dvec3, 2> mean{};  // relative linear RGB over each cluster's inner pixels
  std::array<double, 2> share{};     // of the inner pixels
  int pixels = 0;                    // inner pixels of both clusters
  // The density of pixels between the clusters over the lower of their two peaks, along the line
  // through their centres: near 0 when the threads differ in colour; near 1 when the k-means cut a
  // continuum (threads of one colour, split by their floats' own shading).
  double valley = 1;
  bool separated() const { return valley < kSeparatedValley; }
  static constexpr double kSeparatedValley = 0.1;
};

struct CloseupClusters {
  // On colour and lightness, then on colour alone: a glossy float's highlight is a lightness of
  // its own, and on colour alone two threads of two colours stay apart while the highlight joins
  // its thread. The fit takes the split whose clusters cover what its weave's threads cover.
  std::vector<CloseupSplit> splits;
  double gap_share = 0;  // pixels too dark to be a thread (the gaps between yarns)
  // The scale tag (capture_card.h, id 5) when the close-up holds it, and the spectrum its
  // millimetres give, from which the weave's family gives the ends and picks (thread_counts.h).
  std::optional<CloseupScale> scale;
  std::optional<CloseupSpectrum> spectrum;
  // The swatch's mean radiance straight above in the photos' units (a white diffuser reads 1):
  // the frame's mean off the tag over the tag's white border, times the paper's reflectance. The
  // photos see the swatch from the side; this sees it from above, at the close-up's own exposure.
  // Nothing without the tag, or where the border or the swatch clip.
  std::optional<glm::dvec3> level;
  // Whether any split separates: if none does, the close-up shows one colour.
  bool separated() const {
    for (const CloseupSplit& s : splits)
      if (s.separated()) return true;
    return false;
  }
};

// The threads' pixels of a close-up (the middle 80 % of the frame; clipped pixels, gaps and the
// scale tag left out) split into two clusters both ways, and how well they separate. `response` is the camera's (any of its photos':
// a common scale cancels). A cluster of under 2 % of the inner pixels counts as no cluster (one
// colour). Throws CaptureRejection when the close-up is saturated, shows too few thread pixels,
// or its threads are too fine to leave pixels inside them.
CloseupClusters measure_closeup(const Photo& photo, const ResponseModel& response, const std::string& name);

}  // namespace weft
