#include "bench/filament_peer/filament_frame.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <stdexcept>

#include <filament/Camera.h>
#include <filament/Engine.h>
#include <filament/IndexBuffer.h>
#include <filament/IndirectLight.h>
#include <filament/Material.h>
#include <filament/MaterialInstance.h>
#include <filament/RenderTarget.h>
#include <filament/RenderableManager.h>
#include <filament/Renderer.h>
#include <filament/Scene.h>
#include <filament/SwapChain.h>
#include <filament/Texture.h>
#include <filament/VertexBuffer.h>
#include <filament/View.h>
#include <filament/Viewport.h>
#include <geometry/SurfaceOrientation.h>
#include <image/KtxBundle.h>
#include <image/KtxUtility.h>
#include <utils/EntityManager.h>

#include "peer_materials.h"

// Last: Xlib defines macros (Success, None, Bool) that Filament's headers use as names.
#include <X11/Xlib.h>

namespace weft::peer {

namespace fl = filament;
using fl::math::float3;
using fl::math::float4;
using fl::math::short4;

std::string filament_unavailable() {
  Display* display = XOpenDisplay(nullptr);
  if (!display) {
    const char* name = std::getenv("DISPLAY");
    return std::string("no X display") + (name ? " at DISPLAY=" + std::string(name) : " (DISPLAY unset)") +
           " for Filament's GLX backend (Debian's libfilament has no headless EGL platform; run under xvfb-run -a)";
  }
  XCloseDisplay(display);
  return "";
}

namespace {
float3 f3(const glm::dvec3& v) { return {float(v.x), float(v.y), float(v.z)}; }
}  // namespace

struct FilamentPeer::State {
  fl::Engine* engine = nullptr;
  fl::Renderer* renderer = nullptr;
  fl::Material* cloth = nullptr;
  fl::Material* lambert = nullptr;
  fl::Scene* scene = nullptr;
  utils::Entity camera_entity;
  fl::Camera* camera = nullptr;
  fl::Texture* ibl_texture = nullptr;
  fl::IndirectLight* ibl = nullptr;
  struct Object {
    utils::Entity entity;
    fl::VertexBuffer* vb = nullptr;
    fl::IndexBuffer* ib = nullptr;
    fl::MaterialInstance* mi = nullptr;
    std::vector<float3> positions;  // kept until Filament has uploaded them
    std::vector<short4> tangents;
    std::vector<uint32_t> indices;
  };
  std::vector<std::unique_ptr<Object>> objects;
  glm::dvec3 centre{0.0};
  double radius = 1.0;

  void clear_objects() {
    for (auto& o : objects) {
      scene->remove(o->entity);
      engine->destroy(o->entity);
      engine->destroy(o->mi);
      engine->destroy(o->vb);
      engine->destroy(o->ib);
      utils::EntityManager::get().destroy(o->entity);
    }
    objects.clear();
  }

  void place_camera(const Camera& c, int width, int height) {
    // Near and far around the scene's bounding sphere: depth precision where the scene is.
    const double d = glm::length(c.position - centre);
    const double far_plane = d + 2.0 * radius;
    const double near_plane = std::max(far_plane * 1e-4, 0.5 * (d - radius));
    camera->setProjection(c.fov_deg, double(width) / height, near_plane, far_plane, fl::Camera::Fov::VERTICAL);
    camera->lookAt(f3(c.position), f3(c.target), f3(c.up));
    camera->setExposure(1.0f);
  }

  // One frame, timed: begin (retried while Filament paces frames), render, the readback when
  // asked, end, then flushAndWait, which returns once the driver has run glFinish.
  double frame(fl::View* view, fl::SwapChain* swap, fl::RenderTarget* target,
               fl::backend::PixelBufferDescriptor* readback, int width, int height) {
    const auto t0 = std::chrono::steady_clock::now();
    int tries = 0;
    while (!renderer->beginFrame(swap)) {
      engine->flushAndWait();
      if (++tries > 100) throw std::runtime_error("Filament: beginFrame refused 100 frames in a row");
    }
    renderer->render(view);
    if (readback) renderer->readPixels(target, 0, 0, width, height, std::move(*readback));
    renderer->endFrame();
    engine->flushAndWait();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  }
};

FilamentPeer::FilamentPeer() : s_(std::make_unique<State>()) {
  s_->engine = fl::Engine::create(fl::Engine::Backend::OPENGL);
  if (!s_->engine) throw std::runtime_error("Filament: no OpenGL engine could be created");
  s_->renderer = s_->engine->createRenderer();
  s_->renderer->setClearOptions({.clearColor = {0.0f, 0.0f, 0.0f, 0.0f}, .clear = true, .discard = true});
  s_->cloth = fl::Material::Builder()
                  .package(PEER_MATERIALS_PEER_CLOTH_DATA, size_t(PEER_MATERIALS_PEER_CLOTH_SIZE))
                  .build(*s_->engine);
  s_->lambert = fl::Material::Builder()
                    .package(PEER_MATERIALS_PEER_LAMBERT_DATA, size_t(PEER_MATERIALS_PEER_LAMBERT_SIZE))
                    .build(*s_->engine);
  s_->scene = s_->engine->createScene();
  s_->camera_entity = utils::EntityManager::get().create();
  s_->camera = s_->engine->createCamera(s_->camera_entity);
}

FilamentPeer::~FilamentPeer() {
  State& s = *s_;
  s.clear_objects();
  if (s.ibl) s.engine->destroy(s.ibl);
  if (s.ibl_texture) s.engine->destroy(s.ibl_texture);
  s.engine->destroyCameraComponent(s.camera_entity);
  utils::EntityManager::get().destroy(s.camera_entity);
  s.engine->destroy(s.scene);
  s.engine->destroy(s.cloth);
  s.engine->destroy(s.lambert);
  s.engine->destroy(s.renderer);
  fl::Engine::destroy(&s.engine);
}

void FilamentPeer::set_scene(const Scene& scene, const std::vector<FilamentCloth>& cloth) {
  State& s = *s_;
  size_t cloth_count = 0;
  for (const auto& o : scene.objects) cloth_count += o.is_cloth();
  if (cloth_count != cloth.size())
    throw std::invalid_argument("FilamentPeer::set_scene: " + std::to_string(cloth.size()) + " cloth looks for " +
                                std::to_string(cloth_count) + " cloth objects");
  s.clear_objects();
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  size_t k = 0;
  for (const auto& so : scene.objects) {
    auto o = std::make_unique<State::Object>();
    const TriangleMesh& m = so.mesh;
    const size_t n = m.positions.size();
    o->positions.reserve(n);
    std::vector<float3> normals(n);
    std::vector<float4> tangents(n);
    glm::dvec3 olo(std::numeric_limits<double>::max()), ohi(-std::numeric_limits<double>::max());
    for (size_t i = 0; i < n; ++i) {
      o->positions.push_back(f3(m.positions[i]));
      normals[i] = f3(m.normals[i]);
      const glm::dvec3 t = i < m.warps.size() ? m.warps[i] : unit_tangent(glm::dvec3(1, 0, 0), m.normals[i]);
      tangents[i] = float4(f3(t), 1.0f);
      olo = glm::min(olo, m.positions[i]), ohi = glm::max(ohi, m.positions[i]);
    }
    lo = glm::min(lo, olo), hi = glm::max(hi, ohi);
    // Filament carries the shading frame as one quaternion per vertex.
    auto* orientation = fl::geometry::SurfaceOrientation::Builder()
                            .vertexCount(n)
                            .normals(normals.data())
                            .tangents(tangents.data())
                            .build();
    o->tangents.resize(n);
    orientation->getQuats(o->tangents.data(), n);
    delete orientation;
    for (const auto& t : m.triangles) o->indices.insert(o->indices.end(), t.begin(), t.end());

    o->vb = fl::VertexBuffer::Builder()
                .vertexCount(uint32_t(n))
                .bufferCount(2)
                .attribute(fl::VertexAttribute::POSITION, 0, fl::VertexBuffer::AttributeType::FLOAT3)
                .attribute(fl::VertexAttribute::TANGENTS, 1, fl::VertexBuffer::AttributeType::SHORT4)
                .normalized(fl::VertexAttribute::TANGENTS)
                .build(*s.engine);
    o->vb->setBufferAt(*s.engine, 0, {o->positions.data(), n * sizeof(float3)});
    o->vb->setBufferAt(*s.engine, 1, {o->tangents.data(), n * sizeof(short4)});
    o->ib = fl::IndexBuffer::Builder()
                .indexCount(uint32_t(o->indices.size()))
                .bufferType(fl::IndexBuffer::IndexType::UINT)
                .build(*s.engine);
    o->ib->setBuffer(*s.engine, {o->indices.data(), o->indices.size() * sizeof(uint32_t)});
    if (so.is_cloth()) {
      const FilamentCloth& c = cloth[k++];
      o->mi = s.cloth->createInstance();
      o->mi->setParameter("baseColor", f3(c.base_colour));
      o->mi->setParameter("sheenColor", f3(c.sheen_colour));
      o->mi->setParameter("roughness", float(c.roughness));
    } else {
      o->mi = s.lambert->createInstance();
      o->mi->setParameter("baseColor", f3(so.albedo));
    }
    o->entity = utils::EntityManager::get().create();
    fl::RenderableManager::Builder(1)
        .boundingBox(fl::Box().set(f3(olo), f3(ohi)))
        .material(0, o->mi)
        .geometry(0, fl::RenderableManager::PrimitiveType::TRIANGLES, o->vb, o->ib)
        .culling(false)
        .castShadows(false)
        .receiveShadows(false)
        .build(*s.engine, o->entity);
    s.scene->addEntity(o->entity);
    s.objects.push_back(std::move(o));
  }
  s.centre = 0.5 * (lo + hi);
  s.radius = std::max(0.5 * glm::length(hi - lo), 1e-6);
}

void FilamentPeer::set_ibl(const std::filesystem::path& ktx) {
  State& s = *s_;
  std::ifstream in(ktx, std::ios::binary);
  const std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.empty()) throw std::runtime_error(ktx.string() + ": cannot read the IBL");
  auto* bundle = new image::KtxBundle(bytes.data(), uint32_t(bytes.size()));
  float3 sh[9];
  if (!bundle->getSphericalHarmonics(sh)) {
    delete bundle;
    throw std::runtime_error(ktx.string() + ": no spherical harmonics in its metadata (not a cmgen IBL)");
  }
  if (s.ibl) s.engine->destroy(s.ibl);
  if (s.ibl_texture) s.engine->destroy(s.ibl_texture);
  s.ibl_texture = image::ktx::createTexture(s.engine, bundle, false);  // takes the bundle
  s.ibl = fl::IndirectLight::Builder().reflections(s.ibl_texture).irradiance(3, sh).intensity(1.0f).build(*s.engine);
  s.scene->setIndirectLight(s.ibl);
}

FilamentFrame FilamentPeer::linear(const Camera& camera, int width, int height, int timed_frames) {
  State& s = *s_;
  using fl::Texture;
  fl::SwapChain* swap = s.engine->createSwapChain(uint32_t(width), uint32_t(height));
  Texture* colour = Texture::Builder()
                        .width(width)
                        .height(height)
                        .levels(1)
                        .usage(Texture::Usage::COLOR_ATTACHMENT | Texture::Usage::SAMPLEABLE)
                        .format(Texture::InternalFormat::RGBA32F)
                        .build(*s.engine);
  Texture* depth = Texture::Builder()
                       .width(width)
                       .height(height)
                       .levels(1)
                       .usage(Texture::Usage::DEPTH_ATTACHMENT)
                       .format(Texture::InternalFormat::DEPTH32F)
                       .build(*s.engine);
  fl::RenderTarget* target = fl::RenderTarget::Builder()
                                 .texture(fl::RenderTarget::AttachmentPoint::COLOR, colour)
                                 .texture(fl::RenderTarget::AttachmentPoint::DEPTH, depth)
                                 .build(*s.engine);
  fl::View* view = s.engine->createView();
  view->setScene(s.scene);
  view->setCamera(s.camera);
  view->setViewport({0, 0, uint32_t(width), uint32_t(height)});
  view->setRenderTarget(target);
  view->setPostProcessingEnabled(false);
  view->setShadowingEnabled(false);
  s.place_camera(camera, width, height);

  FilamentFrame f;
  std::vector<double> ms;
  s.frame(view, swap, target, nullptr, width, height);  // warm-up: shader compilation, uploads
  for (int i = 0; i < timed_frames; ++i) ms.push_back(s.frame(view, swap, target, nullptr, width, height));
  // The readback frame, untimed. NaN first: a pixel left NaN was never written back.
  std::vector<float> rgba(size_t(width) * height * 4, std::numeric_limits<float>::quiet_NaN());
  fl::backend::PixelBufferDescriptor read(rgba.data(), rgba.size() * sizeof(float), fl::backend::PixelDataFormat::RGBA,
                                          fl::backend::PixelDataType::FLOAT);
  s.frame(view, swap, target, &read, width, height);
  for (int i = 0; i < 20 && std::isnan(rgba[0]); ++i) s.engine->flushAndWait();
  if (std::isnan(rgba[0])) throw std::runtime_error("Filament: the frame's readback never arrived");
  f.image = Image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float* p = &rgba[(size_t(y) * width + x) * 4];  // a render target's rows come back top first
      f.image.at(x, y) = glm::dvec3(p[0], p[1], p[2]);
    }
  f.frames = timed_frames;
  if (!ms.empty()) {
    std::nth_element(ms.begin(), ms.begin() + ms.size() / 2, ms.end());
    f.median_ms = ms[ms.size() / 2];
  }
  s.engine->destroy(view);
  s.engine->destroy(target);
  s.engine->destroy(colour);
  s.engine->destroy(depth);
  s.engine->destroy(swap);
  s.engine->flushAndWait();
  return f;
}

double FilamentPeer::shipping_ms(const Camera& camera, int width, int height, int timed_frames) {
  State& s = *s_;
  fl::SwapChain* swap = s.engine->createSwapChain(uint32_t(width), uint32_t(height));
  fl::View* view = s.engine->createView();
  view->setScene(s.scene);
  view->setCamera(s.camera);
  view->setViewport({0, 0, uint32_t(width), uint32_t(height)});
  view->setShadowingEnabled(false);
  s.place_camera(camera, width, height);
  std::vector<double> ms;
  s.frame(view, swap, nullptr, nullptr, width, height);
  for (int i = 0; i < timed_frames; ++i) ms.push_back(s.frame(view, swap, nullptr, nullptr, width, height));
  s.engine->destroy(view);
  s.engine->destroy(swap);
  s.engine->flushAndWait();
  if (ms.empty()) return 0.0;
  std::nth_element(ms.begin(), ms.begin() + ms.size() / 2, ms.end());
  return ms[ms.size() / 2];
}

}  // namespace weft::peer
