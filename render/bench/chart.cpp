#include "bench/chart.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>

#include "files/atomic_file.h"
#include "image/image.h"

namespace weft::bench {

namespace {

// 3×5 glyphs, rows top to bottom; lower case is drawn as upper case.
const std::map<char, const char*>& font() {
  static const std::map<char, const char*> f = {
      {'A', ".#.#.#####.##.#"}, {'B', "##.#.###.#.###."}, {'C', ".###..#..#...##"}, {'D', "##.#.##.##.###."},
      {'E', "####..##.#..###"}, {'F', "####..##.#..#.."}, {'G', ".###..#.##.#.##"}, {'H', "#.##.#####.##.#"},
      {'I', "###.#..#..#.###"}, {'J', "..#..#..##.#.#."}, {'K', "#.##.###.#.##.#"}, {'L', "#..#..#..#..###"},
      {'M', "#.########.##.#"}, {'N', "##.#.##.##.##.#"}, {'O', "####.##.##.####"}, {'P', "##.#.###.#..#.."},
      {'Q', "####.##.####..#"}, {'R', "##.#.###.#.##.#"}, {'S', ".###...#...###."}, {'T', "###.#..#..#..#."},
      {'U', "#.##.##.##.####"}, {'V', "#.##.##.##.#.#."}, {'W', "#.##.########.#"}, {'X', "#.##.#.#.#.##.#"},
      {'Y', "#.##.#.#..#..#."}, {'Z', "###..#.#.#..###"}, {'0', "####.##.##.####"}, {'1', ".#.##..#..#.###"},
      {'2', "##...#.#.#..###"}, {'3', "##...#.#...###."}, {'4', "#.##.####..#..#"}, {'5', "####..##...###."},
      {'6', ".###..####.####"}, {'7', "###..#.#..#..#."}, {'8', "####.#####.####"}, {'9', "####.####..###."},
      {'.', ".............#."}, {'-', "......###......"}, {'/', "..#..#.#.#..#.."}, {'%', "#.#..#.#.#..#.#"},
      {'(', ".#.#..#..#...#."}, {')', ".#...#..#..#.#."}, {'=', "...###...###..."}, {':', "....#.....#...."},
      {'_', "............###"}, {',', "..........#.#.."}, {'<', "..#.#.#...#...#"}, {'>', "#...#...#.#.#.."},
      {'*', "...#.#.#.#.#..."}, {'+', "....#.###.#...."}};
  return f;
}

struct Raster {
  int w, h;
  std::vector<unsigned char> px;
  Raster(int w_, int h_) : w(w_), h(h_), px(size_t(w_) * h_ * 3, 255) {}
  void set(int x, int y, const unsigned char* c) {
    if (x < 0 || y < 0 || x >= w || y >= h) return;
    std::copy(c, c + 3, &px[(size_t(y) * w + x) * 3]);
  }
  void line(double x0, double y0, double x1, double y1, const unsigned char* c, int thick = 1) {
    const int n = int(std::max(std::abs(x1 - x0), std::abs(y1 - y0))) + 1;
    for (int i = 0; i <= n; ++i) {
      const double t = double(i) / n;
      const int x = int(std::lround(x0 + t * (x1 - x0))), y = int(std::lround(y0 + t * (y1 - y0)));
      for (int dy = 0; dy < thick; ++dy)
        for (int dx = 0; dx < thick; ++dx) set(x + dx - thick / 2, y + dy - thick / 2, c);
    }
  }
  void disc(double cx, double cy, double r, const unsigned char* c) {
    for (int y = int(cy - r) - 1; y <= int(cy + r) + 1; ++y)
      for (int x = int(cx - r) - 1; x <= int(cx + r) + 1; ++x)
        if ((x - cx) * (x - cx) + (y - cy) * (y - cy) <= r * r) set(x, y, c);
  }
  // Text with 3×5 glyphs scaled by `s`; returns the width drawn.
  int text(int x, int y, const std::string& s, const unsigned char* c, int scale = 2) {
    int cx = x;
    for (char ch : s) {
      const char up = char(std::toupper(static_cast<unsigned char>(ch)));
      auto it = font().find(up);
      if (it != font().end()) {
        const std::string g = it->second;
        for (int i = 0; i < 15 && i < int(g.size()); ++i)
          if (g[i] == '#')
            for (int dy = 0; dy < scale; ++dy)
              for (int dx = 0; dx < scale; ++dx) set(cx + (i % 3) * scale + dx, y + (i / 3) * scale + dy, c);
      }
      cx += 4 * scale;
    }
    return cx - x;
  }
};

// One colour per method for up to 16 methods, distinct side by side in the legend.
const unsigned char kPalette[][3] = {{31, 119, 180},  {214, 39, 40},  {44, 160, 44},   {148, 103, 189},
                                     {255, 127, 14},  {140, 86, 75},  {227, 119, 194}, {23, 190, 207},
                                     {188, 189, 34},  {0, 0, 128},    {128, 128, 128}, {174, 199, 232},
                                     {152, 223, 138}, {255, 152, 150}, {128, 0, 0},    {255, 187, 120}};
constexpr int kPaletteSize = int(sizeof kPalette / sizeof kPalette[0]);
const unsigned char kBlack[3] = {0, 0, 0}, kGrid[3] = {220, 220, 220}, kFront[3] = {90, 90, 90};

std::string decade_label(int e) {
  if (e >= 0 && e <= 5) {
    char b[16];
    std::snprintf(b, sizeof b, "%.0f", std::pow(10.0, e));
    return b;
  }
  if (e < 0 && e >= -4) {
    char b[16];
    std::snprintf(b, sizeof b, "%.*f", -e, std::pow(10.0, e));
    return b;
  }
  return "1E" + std::to_string(e);
}

}  // namespace

std::vector<ChartMarker> chart_markers(const std::vector<ChartPoint>& points) {
  std::vector<ChartMarker> m;
  std::map<std::string, std::array<double, 3>> acc;  // Σ log ms, Σ log err, count
  for (const auto& p : points) {
    if (!(p.ms > 0.0) || !(p.relative_rmse > 0.0)) continue;
    if (!acc.count(p.method)) m.push_back({p.method, 0, 0, false});
    auto& a = acc[p.method];
    a[0] += std::log(p.ms), a[1] += std::log(p.relative_rmse), a[2] += 1;
  }
  for (auto& k : m) {
    const auto& a = acc[k.method];
    k.ms = std::exp(a[0] / a[2]), k.relative_rmse = std::exp(a[1] / a[2]);
  }
  for (auto& k : m) {
    k.pareto = true;
    for (const auto& o : m)
      if (&o != &k && o.ms <= k.ms && o.relative_rmse <= k.relative_rmse &&
          (o.ms < k.ms || o.relative_rmse < k.relative_rmse))
        k.pareto = false;
  }
  return m;
}

void write_chart_png(const std::filesystem::path& file, const std::vector<ChartPoint>& points,
                     const std::string& title) {
  const int W = 960, H = 600, left = 90, right = 290, top = 50, bottom = 70;
  Raster r(W, H);
  const auto markers = chart_markers(points);
  double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
  for (const auto& p : points)
    if (p.ms > 0 && p.relative_rmse > 0) {
      xmin = std::min(xmin, p.ms), xmax = std::max(xmax, p.ms);
      ymin = std::min(ymin, p.relative_rmse), ymax = std::max(ymax, p.relative_rmse);
    }
  if (xmin > xmax) xmin = 1, xmax = 10, ymin = 0.01, ymax = 1;
  const int ex0 = int(std::floor(std::log10(xmin))), ex1 = std::max(ex0 + 1, int(std::ceil(std::log10(xmax))));
  const int ey0 = int(std::floor(std::log10(ymin))), ey1 = std::max(ey0 + 1, int(std::ceil(std::log10(ymax))));
  const double pw = W - left - right, ph = H - top - bottom;
  auto X = [&](double ms) { return left + (std::log10(ms) - ex0) / (ex1 - ex0) * pw; };
  auto Y = [&](double e) { return top + ph - (std::log10(e) - ey0) / (ey1 - ey0) * ph; };
  for (int e = ex0; e <= ex1; ++e) {
    r.line(X(std::pow(10.0, e)), top, X(std::pow(10.0, e)), top + ph, kGrid);
    const std::string l = decade_label(e);
    r.text(int(X(std::pow(10.0, e))) - int(l.size()) * 4, top + int(ph) + 8, l, kBlack);
  }
  for (int e = ey0; e <= ey1; ++e) {
    r.line(left, Y(std::pow(10.0, e)), left + pw, Y(std::pow(10.0, e)), kGrid);
    const std::string l = decade_label(e);
    r.text(left - 8 - int(l.size()) * 8, int(Y(std::pow(10.0, e))) - 5, l, kBlack);
  }
  r.line(left, top, left, top + ph, kBlack, 2);
  r.line(left, top + ph, left + pw, top + ph, kBlack, 2);
  r.text(left, 15, title, kBlack);
  r.text(left + int(pw) / 2 - 90, H - 30, "MS PER FRAME (LOG)", kBlack);
  r.text(8, top - 22, "REL. RMSE (LOG)", kBlack);

  std::map<std::string, int> colour;
  for (const auto& m : markers) colour.emplace(m.method, int(colour.size()) % kPaletteSize);
  for (const auto& p : points)
    if (p.ms > 0 && p.relative_rmse > 0 && colour.count(p.method)) r.disc(X(p.ms), Y(p.relative_rmse), 2.5, kPalette[colour[p.method]]);
  std::vector<ChartMarker> front;
  for (const auto& m : markers)
    if (m.pareto) front.push_back(m);
  std::sort(front.begin(), front.end(), [](const auto& a, const auto& b) { return a.ms < b.ms; });
  for (size_t i = 1; i < front.size(); ++i)
    r.line(X(front[i - 1].ms), Y(front[i - 1].relative_rmse), X(front[i].ms), Y(front[i].relative_rmse), kFront, 2);
  int ly = top + 10;
  for (const auto& m : markers) {
    r.disc(X(m.ms), Y(m.relative_rmse), 7.5, kBlack);
    r.disc(X(m.ms), Y(m.relative_rmse), 6, kPalette[colour[m.method]]);
    r.disc(W - right + 20, ly + 5, 6, kPalette[colour[m.method]]);
    r.text(W - right + 34, ly, m.method + (m.pareto ? " *" : ""), kBlack);
    ly += 24;
  }
  r.text(W - right + 14, ly + 10, "* PARETO FRONT", kFront);
  r.text(W - right + 14, ly + 30, "DOTS: CASES", kFront);
  write_png_rgb8(W, H, r.px, file);
}

}  // namespace weft::bench
