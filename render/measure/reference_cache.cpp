#include "measure/reference_cache.h"

#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "files/atomic_file.h"

namespace weft::bench {

InputHash& add_file(InputHash& h, const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  std::ostringstream s;
  s << in.rdbuf();
  return h.add(s.str());
}

InputHash& add_mesh(InputHash& h, const TriangleMesh& mesh) {
  for (const auto* attribute : {&mesh.positions, &mesh.normals, &mesh.warps})
    h.add(std::string_view(reinterpret_cast<const char*>(attribute->data()), attribute->size() * sizeof(glm::dvec3)));
  return h.add(std::string_view(reinterpret_cast<const char*>(mesh.triangles.data()),
                                mesh.triangles.size() * sizeof(mesh.triangles[0])));
}

std::optional<CachedReference> load_reference(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  char magic[8];
  int32_t w = 0, h = 0;
  in.read(magic, 8);
  in.read(reinterpret_cast<char*>(&w), 4);
  in.read(reinterpret_cast<char*>(&h), 4);
  if (!in || std::memcmp(magic, "WEFTREF1", 8) != 0 || w < 1 || h < 1 || w > 16384 || h > 16384) return std::nullopt;
  CachedReference r{Image(w, h), std::vector<PixelKind>(size_t(w) * h)};
  in.read(reinterpret_cast<char*>(r.image.pixels.data()), std::streamsize(r.image.pixels.size() * sizeof(glm::dvec3)));
  in.read(reinterpret_cast<char*>(r.kinds.data()), std::streamsize(r.kinds.size()));
  if (!in) return std::nullopt;  // truncated: render again
  return r;
}

void store_reference(const std::filesystem::path& file, const CachedReference& r) {
  std::filesystem::create_directories(file.parent_path());
  std::ostringstream out(std::ios::binary);
  const int32_t w = r.image.width, h = r.image.height;
  out.write("WEFTREF1", 8);
  out.write(reinterpret_cast<const char*>(&w), 4);
  out.write(reinterpret_cast<const char*>(&h), 4);
  out.write(reinterpret_cast<const char*>(r.image.pixels.data()), std::streamsize(r.image.pixels.size() * sizeof(glm::dvec3)));
  out.write(reinterpret_cast<const char*>(r.kinds.data()), std::streamsize(r.kinds.size()));
  write_file_atomically(file, out.view());
}

std::optional<TangentConvergence> load_convergence(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) return std::nullopt;
  std::string magic, w1, w2, w3, w4;
  TangentConvergence c;
  int converged = 0;
  in >> magic >> w1 >> c.samples >> w2 >> converged >> w3 >> c.cloth_pixels >> w4 >> c.seconds;
  if (!in || magic != "WEFTNJ1" || w1 != "samples" || w2 != "converged" || w3 != "cloth_pixels" || w4 != "seconds" ||
      c.samples < 1)
    return std::nullopt;
  c.converged = converged != 0;
  std::string line;
  std::getline(in, line);  // the rest of the header line
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string word, extra;
    TangentStep step;
    if (!(fields >> word >> step.samples >> step.finer >> step.relative_change) || word != "step" || fields >> extra)
      return std::nullopt;
    c.steps.push_back(step);
  }
  return c;
}

void store_convergence(const std::filesystem::path& file, const TangentConvergence& c) {
  std::filesystem::create_directories(file.parent_path());
  std::ostringstream out;
  out.precision(17);
  out << "WEFTNJ1\nsamples " << c.samples << " converged " << (c.converged ? 1 : 0) << " cloth_pixels "
      << c.cloth_pixels << " seconds " << c.seconds << "\n";
  for (const auto& s : c.steps) out << "step " << s.samples << " " << s.finer << " " << s.relative_change << "\n";
  write_file_atomically(file, out.view());
}

}  // namespace weft::bench
