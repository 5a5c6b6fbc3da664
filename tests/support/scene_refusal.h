#pragma once
// What a scene loader refuses: the SceneError's message when `load` throws one, else empty.
#include <functional>
#include <string>

#include "scene/scene.h"

namespace weft::test {

inline std::string refusal(const std::function<void()>& load) {
  try {
    load();
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

}  // namespace weft::test
