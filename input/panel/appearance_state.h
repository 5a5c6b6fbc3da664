#pragma once
// What the knobs decide about the picture, in the renderer's terms, as a plain value that can be
// copied between threads without locks. The renderer applies it to the selected preset:
//   A = albedo (RGB), γ_s = preset γ_s · gamma_scale, γ_v = preset γ_v · gamma_scale
// (both lobes scale together so their ratio stays the preset's), and rotates the environment
// about +Z by env_rotation_deg.
//
// A new knob is a field here, its way home in appearance_blend.h, and its command in the
// kiosk's look applier (render/kiosk/look_applier.h); comparison is every field, by default.
#include <cstdint>
#include <type_traits>

namespace weft::input {

struct ThreadAppearance {
  float albedo[3] = {0.5f, 0.5f, 0.5f};  // A, linear RGB
  float gamma_scale = 1.0f;              // multiplies γ_s and γ_v
  bool operator==(const ThreadAppearance&) const = default;
};

enum class ThreadSelection : uint8_t { both = 0, warp = 1, weft = 2 };

struct AppearanceState {
  uint32_t preset_index = 0;       // into the preset list the mapper was given (the colourway's, with colourways)
  uint32_t colourway = 0;          // into the colourways the mapper was given (0 without any)
  ThreadAppearance thread[2];      // [0] warp (thread 1), [1] weft (thread 2)
  float env_rotation_deg = 0.0f;   // [0, 360)
  float zoom = 0.0f;               // 0: the scene's camera … 1: its close-up
  ThreadSelection selection = ThreadSelection::both;  // which thread the dials edit (on-screen hint)
  bool operator==(const AppearanceState&) const = default;
};
static_assert(std::is_trivially_copyable_v<AppearanceState>);

}  // namespace weft::input
