#pragma once
// The error every GL wrapper and GPU component throws, and the GL error-flag check.
#include <stdexcept>

namespace weft::gpu {

class GpuError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

// Throws GpuError "<what>: GL error 0x…" when the GL error flag is set (after uploads).
void check_gl(const char* what);

}  // namespace weft::gpu
