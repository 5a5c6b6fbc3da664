#pragma once
// Included by a parity test: every program it builds traps GLSL's undefined cases as NaN
// (shader_preamble's WEFT_STRICT_GLSL), so a shader that llvmpipe answers kindly but a GPU
// driver answers with NaN (pow(0, 0)) fails here, on the CI's llvmpipe, against the C++.
#include <cstdlib>

namespace weft::test {
inline const bool kStrictGlsl = [] { return setenv("WEFT_STRICT_GLSL", "1", 0) == 0; }();
}  // namespace weft::test
