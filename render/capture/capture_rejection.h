#pragma once
// A capture `weft capture` cannot fit, for a reason the photographer can fix (the card out of
// frame, a saturated or blurred photo, too few turns of the swatch): exit code 2.
#include <stdexcept>

namespace weft {

class CaptureRejection : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

}  // namespace weft
