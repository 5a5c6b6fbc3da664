#pragma once
// Hue/saturation/value <-> RGB (the hexcone model), so a shopper turns "hue" and "brightness"
// instead of three channels. Hue in degrees [0, 360).
namespace weft::input {

struct Hsv {
  double h = 0, s = 0, v = 0;
};
Hsv hsv_from_rgb(double r, double g, double b);
void rgb_from_hsv(const Hsv& c, double rgb[3]);

}  // namespace weft::input
