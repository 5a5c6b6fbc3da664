#include "image/image.h"

#include "image/tone_map.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>

#include <ImfFrameBuffer.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfChannelList.h>
#include <ImfHeader.h>
#include <png.h>

#include "files/atomic_file.h"

namespace weft {

void write_exr(const Image& image, const std::filesystem::path& file) {
  try {
    Imf::Header header(image.width, image.height);
    header.compression() = Imf::ZIP_COMPRESSION;
    for (const char* c : {"R", "G", "B"}) header.channels().insert(c, Imf::Channel(Imf::FLOAT));
    std::vector<float> rgb(image.pixels.size() * 3);
    for (size_t i = 0; i < image.pixels.size(); ++i)
      for (int c = 0; c < 3; ++c) rgb[3 * i + c] = static_cast<float>(image.pixels[i][c]);
    Imf::FrameBuffer fb;
    const size_t xs = 3 * sizeof(float), ys = xs * image.width;
    char* base = reinterpret_cast<char*>(rgb.data());
    fb.insert("R", Imf::Slice(Imf::FLOAT, base, xs, ys));
    fb.insert("G", Imf::Slice(Imf::FLOAT, base + sizeof(float), xs, ys));
    fb.insert("B", Imf::Slice(Imf::FLOAT, base + 2 * sizeof(float), xs, ys));
    write_file_atomically(file, [&](const std::filesystem::path& temporary) {
      Imf::OutputFile out(temporary.c_str(), header);
      out.setFrameBuffer(fb);
      out.writePixels(image.height);
    });
  } catch (const std::exception& e) {
    throw std::runtime_error("cannot write EXR " + file.string() + ": " + e.what());
  }
}

Image read_exr(const std::filesystem::path& file) {
  try {
    Imf::InputFile in(file.c_str());
    const Imath::Box2i dw = in.header().dataWindow();
    const int w = dw.max.x - dw.min.x + 1, h = dw.max.y - dw.min.y + 1;
    for (const char* c : {"R", "G", "B"})
      if (!in.header().channels().findChannel(c)) throw std::runtime_error(std::string("no ") + c + " channel");
    std::vector<float> rgb(static_cast<size_t>(w) * h * 3);
    const size_t xs = 3 * sizeof(float), ys = xs * static_cast<size_t>(w);
    // The slices are addressed by absolute pixel coordinates: shift the base to the window's origin.
    char* base = reinterpret_cast<char*>(rgb.data()) - static_cast<std::ptrdiff_t>(dw.min.x) * std::ptrdiff_t(xs) -
                 static_cast<std::ptrdiff_t>(dw.min.y) * std::ptrdiff_t(ys);
    Imf::FrameBuffer fb;
    fb.insert("R", Imf::Slice(Imf::FLOAT, base, xs, ys));
    fb.insert("G", Imf::Slice(Imf::FLOAT, base + sizeof(float), xs, ys));
    fb.insert("B", Imf::Slice(Imf::FLOAT, base + 2 * sizeof(float), xs, ys));
    in.setFrameBuffer(fb);
    in.readPixels(dw.min.y, dw.max.y);
    Image image(w, h);
    for (size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = glm::dvec3(rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]);
    return image;
  } catch (const std::exception& e) {
    throw std::runtime_error("cannot read EXR " + file.string() + ": " + e.what());
  }
}

namespace {

// One PNG of `height` rows, each filled by row(y, bytes).
template <class Row>
void write_rgb_png(int width, int height, const std::filesystem::path& file, Row row_at) {
  write_file_atomically(file, [&](const std::filesystem::path& temporary) {
    std::unique_ptr<FILE, int (*)(FILE*)> fp(std::fopen(temporary.c_str(), "wb"), std::fclose);
    if (!fp) throw std::runtime_error("cannot open " + file.string() + " for writing");
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!png || !info) {
      png_destroy_write_struct(&png, &info);
      throw std::runtime_error("libpng: out of memory writing " + file.string());
    }
    std::vector<unsigned char> row(static_cast<size_t>(width) * 3);
    if (setjmp(png_jmpbuf(png))) {
      png_destroy_write_struct(&png, &info);
      throw std::runtime_error("libpng: failed writing " + file.string());
    }
    png_init_io(png, fp.get());
    png_set_IHDR(png, info, width, height, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (int y = 0; y < height; ++y) {
      row_at(y, row.data());
      png_write_row(png, row.data());
    }
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
  });
}

}  // namespace

void write_png(const Image& image, const std::filesystem::path& file, double exposure) {
  write_rgb_png(image.width, image.height, file, [&](int y, unsigned char* row) {
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c) row[3 * x + c] = static_cast<unsigned char>(std::lround(255.0 * display_value(image.at(x, y)[c], exposure)));
  });
}

void write_png_rgb8(int width, int height, const std::vector<unsigned char>& rgb, const std::filesystem::path& file) {
  if (rgb.size() != static_cast<size_t>(width) * height * 3)
    throw std::invalid_argument("write_png_rgb8: " + std::to_string(rgb.size()) + " bytes for " + std::to_string(width) + "x" + std::to_string(height));
  write_rgb_png(width, height, file, [&](int y, unsigned char* row) {
    std::copy_n(rgb.data() + static_cast<size_t>(y) * width * 3, static_cast<size_t>(width) * 3, row);
  });
}

double auto_exposure(const Image& image, const std::vector<bool>& include, double bias_ev) {
  return metered_exposure(log_average_luminance(image.pixels, include), bias_ev);
}

}  // namespace weft
