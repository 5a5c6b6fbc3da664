#pragma once
// What the kiosk asks of the libcamera light probe: which camera, the frame size, how long to
// wait. Shared by the kiosk (no libcamera) and the plugin that drives libcamera.
#include <chrono>
#include <string>

namespace weft {

struct LibcameraOptions {
  std::string camera_id;  // empty: the first camera libcamera lists
  int width = 640;
  int height = 480;
  std::chrono::milliseconds timeout{2000};
  int settle_retries = 6;  // frames to wait for the requested exposure to take effect
};

}  // namespace weft
