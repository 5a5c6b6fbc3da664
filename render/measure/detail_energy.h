#pragma once
// The artefact measure for product files: a frame's fine detail (its luminance minus that
// luminance blurred) block by block, against a reference frame's in the same block. A moiré star
// at a UV pole or a dotted seam is fine detail the reference does not have; a weave the reference
// shows too is not an artefact.
#include <vector>

#include "image/image.h"

namespace weft::bench {

inline constexpr int kDetailBlock = 32;          // pixels a block side
inline constexpr double kDetailBlurSigma = 2.0;  // pixels: detail is what changes within a few pixels

// Mean squared (Y − blur(Y)) over each kDetailBlock² block (the last row and column of blocks
// take what is left), Y the Rec. 709 luminance, blur a Gaussian of kDetailBlurSigma (edges
// clamped). Row-major, (width + block − 1)/block blocks a row.
struct DetailBlocks {
  int columns = 0, rows = 0;
  std::vector<double> energy;
};
DetailBlocks detail_energy(const Image& image);

// The worst block of `method` against `reference` (images of equal size): its energy over the
// reference's, the reference's counted as at least (1 % of the reference's mean luminance)², so
// that a flat block with a trace of detail is not a division by nothing. `over`: blocks whose
// ratio exceeds `limit`. Throws std::invalid_argument on a size mismatch or an empty image.
struct DetailRatio {
  double worst = 0.0;
  int worst_column = 0, worst_row = 0;
  size_t over = 0, blocks = 0;
};
DetailRatio detail_ratio(const Image& method, const Image& reference, double limit = 2.0);

}  // namespace weft::bench
