// The kiosk's zoom against closed forms: the dolly's ends are the two cameras, its distance to
// the target is geometric in t (each step the same factor), and the easing follows an exponential
// and snaps at the end.
#include <gtest/gtest.h>

#include <cmath>

#include "kiosk/camera_zoom.h"

using namespace weft;

TEST(CameraZoom, DollyRunsGeometricallyFromTheViewToTheCloseUp) {
  Camera far, close;
  far.position = {0, -4, 1};
  far.target = {0, 0, 0.5};
  far.fov_deg = 40;
  close.position = {0.02, -0.35, 0.55};
  close.target = {0, -0.3, 0.5};
  close.fov_deg = 30;
  const Camera a = dolly(far, close, 0.0), b = dolly(far, close, 1.0);
  EXPECT_EQ(a.position, far.position);
  EXPECT_EQ(b.position, close.position);
  const double d0 = glm::length(far.position - far.target), d1 = glm::length(close.position - close.target);
  for (double t : {0.25, 0.5, 0.75}) {
    const Camera c = dolly(far, close, t);
    EXPECT_NEAR(glm::length(c.position - c.target), d0 * std::pow(d1 / d0, t), 1e-9 * d0) << t;
    EXPECT_NEAR(c.fov_deg, 40.0 - 10.0 * t, 1e-12);
  }
  EXPECT_EQ(dolly(far, close, -3.0).position, far.position);  // clamped
  EXPECT_EQ(dolly(far, close, 7.0).position, close.position);
}

TEST(CameraZoom, EasesExponentiallyAndSnaps) {
  EXPECT_NEAR(ease_zoom(0.0, 1.0, 0.25, 0.25), 1.0 - std::exp(-1.0), 1e-12);
  EXPECT_EQ(ease_zoom(0.9995, 1.0, 0.01), 1.0);
  EXPECT_EQ(ease_zoom(0.3, 0.0, 1e9), 0.0);
  EXPECT_EQ(ease_zoom(0.5, 1.0, -1.0), 0.5);  // a clock that steps back changes nothing
}
