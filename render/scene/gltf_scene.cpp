#include "scene/gltf_scene.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>

#include "scene/gltf_draco.h"
#include "scene/gltf_geometry.h"
#include "scene/gltf_loadable.h"
#include "scene/gltf_materials.h"
#include "scene/gltf_meshopt.h"
#include "scene/gltf_sheen_fabric.h"
#include "scene/gltf_variants.h"
#include "scene/bounds.h"

namespace weft {

namespace {

constexpr const char* kDefaultEnvironment = "studio";

// Images are decoded by the importer, and only those a cloth's texture uses (thread_maps.h, with
// its caps). tinygltf hands a data URI's decoded bytes here, kept as they are; a bufferView's
// image is read by the importer within its buffer's bounds, an external file from its uri.
bool keep_image_bytes(tinygltf::Image* image, const int, std::string*, std::string*, int, int, const unsigned char* bytes,
                      int size, void*) {
  if (image->bufferView < 0 && bytes && size > 0) {
    image->image.assign(bytes, bytes + size);
    image->as_is = true;
  }
  return true;
}

// Compressed and quantized geometry, decoded before any accessor is read (gltf_draco.h,
// gltf_meshopt.h) or read as it is (integer accessors).
constexpr const char* kDracoCompression = "KHR_draco_mesh_compression";
constexpr const char* kMeshoptCompression = "EXT_meshopt_compression";
constexpr const char* kKhrMeshoptCompression = "KHR_meshopt_compression";
constexpr const char* kMeshQuantization = "KHR_mesh_quantization";

// External buffers: only regular files within the size cap (no devices, no FIFOs, nothing that
// would take the whole memory), and nothing is ever written.
bool read_buffer_file(std::vector<unsigned char>* out, std::string* err, const std::string& path, void*) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    if (err) *err += "File not found : " + path + "\n";
    return false;
  }
  if (std::filesystem::file_size(path, ec) > kGltfMaxFileBytes) {
    if (err) *err += "buffer file " + path + " exceeds the importer's size limit\n";
    return false;
  }
  return tinygltf::ReadWholeFile(out, err, path, nullptr);
}

bool refuse_write(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  if (err) *err += "the importer writes no files\n";
  return false;
}

// Looks at the bounds' centre from the front left and above (Weft's cameras face +y), far enough
// that the bounding sphere fills the vertical field of view.
Camera framed_camera(const Scene& s) {
  const Bounds b = product_bounds(s);
  Camera c;
  c.fov_deg = 40.0;
  const glm::dvec3 centre = b.centre();
  const double radius = std::max(0.5 * glm::length(b.extent()), 1e-3);
  const double distance = 1.1 * radius / std::sin(0.5 * c.fov_deg * 3.14159265358979323846 / 180.0);
  c.target = centre;
  c.position = centre + distance * glm::normalize(glm::dvec3(0.45, -1.0, 0.55));
  c.up = {0, 0, 1};
  return c;
}

// The scene of a loaded, decompressed model: one object per material slot that primitives wear,
// named after its material, dressed by GltfMaterials; the file's camera or one framed on it.
Scene import_model(const tinygltf::Model& m, const std::string& origin, const std::filesystem::path& base_dir,
                   const GltfImportOptions& options) {
  std::vector<std::string> notes;  // what the import decided, for the log (Scene::warnings)
  GltfMaterials materials(m, origin, base_dir, options, notes);
  GltfVariants variants(m, origin);
  GltfGeometry geometry(m, origin, notes);
  Scene s;
  s.environment = kDefaultEnvironment;
  std::optional<Camera> camera;
  for (const auto& [node, world] : geometry.node_instances()) {
    if (!camera) camera = geometry.perspective_camera(node, world);
    const tinygltf::Node& n = m.nodes[size_t(node)];
    if (n.mesh < 0) continue;
    if (static_cast<size_t>(n.mesh) >= m.meshes.size())
      throw SceneError(origin + ": mesh " + std::to_string(n.mesh) + " does not exist");
    const tinygltf::Mesh& mesh = m.meshes[size_t(n.mesh)];
    for (size_t p = 0; p < mesh.primitives.size(); ++p) {
      const tinygltf::Primitive& primitive = mesh.primitives[p];
      const std::string where = "meshes[" + std::to_string(n.mesh) + "].primitives[" + std::to_string(p) + "]";
      geometry.check_primitive(primitive, where);
      variants.map(primitive, where);
      geometry.add_primitive(primitive, world, materials.fabric(size_t(primitive.material + 1)), where);
    }
  }
  geometry.turn_inward_parts(camera ? std::optional<glm::dvec3>(camera->position) : std::nullopt);
  std::vector<std::string> object_names(materials.slots());  // per slot, "" when it has no object
  for (size_t i = 0; i < materials.slots(); ++i) {
    if (!geometry.has_triangles(i)) continue;
    SceneObject o;
    o.name = i == 0 ? std::string("default") : m.materials[i - 1].name;
    if (o.name.empty()) o.name = "material_" + std::to_string(i - 1);
    const std::string stem = o.name;
    for (int k = 2; std::any_of(s.objects.begin(), s.objects.end(), [&](const SceneObject& x) { return x.name == o.name; });
         ++k)
      o.name = stem + "_" + std::to_string(k);  // material names need not be unique
    o.mesh = geometry.take_mesh(i);
    o.repair = geometry.repair(i);
    materials.dress(o, i);
    object_names[i] = o.name;
    s.objects.push_back(std::move(o));
  }
  if (s.objects.empty()) throw SceneError(origin + ": no triangle meshes in the scene");
  s.colourways = variants.colourways(object_names, materials);
  try {
    check_colourways(s, origin);
  } catch (const SceneError& e) {
    throw SceneError(std::string(e.what()) + " (from extensions." + kVariants + ")");
  }
  s.camera = camera ? *camera : framed_camera(s);
  for (const std::string& n : notes) s.warnings.push_back(origin + ": " + n);
  return s;
}

}  // namespace

bool is_gltf_path(const std::string& name) {
  std::string ext = std::filesystem::path(name).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".gltf" || ext == ".glb";
}

Scene parse_gltf_scene(const std::string& bytes, const std::string& origin, const std::filesystem::path& base_dir,
                       const GltfImportOptions& options) {
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(keep_image_bytes, nullptr);
  loader.SetFsCallbacks({tinygltf::FileExists, tinygltf::ExpandFilePath, read_buffer_file, refuse_write, nullptr});
  tinygltf::Model model;
  std::string err, warn;
  const bool binary = bytes.size() >= 4 && bytes.compare(0, 4, "glTF") == 0;
  bool ok = false;
  try {
    const std::string loadable = loadable_by_tinygltf(bytes);
    ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, reinterpret_cast<const unsigned char*>(loadable.data()),
                                              static_cast<unsigned int>(loadable.size()), base_dir.string())
                : loader.LoadASCIIFromString(&model, &err, &warn, loadable.data(), static_cast<unsigned int>(loadable.size()),
                                             base_dir.string());
  } catch (const std::exception& e) {
    ok = false;
    err = e.what();
  }
  if (!ok) {
    while (!err.empty() && (err.back() == '\n' || err.back() == ' ')) err.pop_back();
    std::replace(err.begin(), err.end(), '\n', ';');
    throw SceneError(origin + ": not a usable glTF 2.0 file (" + (err.empty() ? std::string("no reason given") : err) + ")");
  }
  // A required extension Weft does not read is refused by name (its data would read as garbage),
  // an optional one is a remark for the log.
  const std::set<std::string> read = {kTextureTransform,   kVariants,         kDracoCompression, kMeshoptCompression,
                                      kKhrMeshoptCompression, kMeshQuantization, kSheenExtension};
  for (const std::string& e : model.extensionsRequired)
    if (!read.count(e))
      throw SceneError(origin + ": requires the glTF extension " + e +
                     ", which Weft cannot read (export the file without it)");
  std::vector<std::string> remarks;
  for (const std::string& e : model.extensionsUsed)
    if (!read.count(e)) remarks.push_back("uses the glTF extension " + e + ", which Weft ignores");
  decode_meshopt_buffer_views(model, origin);
  decode_draco_primitives(model, origin);
  Scene s = import_model(model, origin, base_dir, options);
  for (const std::string& r : remarks) s.warnings.push_back(origin + ": " + r);
  // tinygltf's warnings, one per line, for the log: what it let through is worth a look.
  std::stringstream lines(warn);
  for (std::string line; std::getline(lines, line);)
    if (!line.empty()) s.warnings.push_back(origin + ": " + line);
  s.name = std::filesystem::path(origin).stem().string();
  s.description = "glTF " + origin;
  return s;
}

Scene load_gltf_scene(const std::filesystem::path& file, const GltfImportOptions& options) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(file, ec);
  if (ec) throw SceneError("cannot open glTF file " + file.string() + " (" + ec.message() + ")");
  if (size > kGltfMaxFileBytes)
    throw SceneError(file.string() + ": " + std::to_string(size) + " bytes exceed the importer's limit");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw SceneError("cannot open glTF file " + file.string());
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_gltf_scene(ss.str(), file.string(), file.parent_path(), options);
}

}  // namespace weft
