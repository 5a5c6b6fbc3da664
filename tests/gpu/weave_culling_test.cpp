// The weave layer's vertex pass for the vertices a frame shows only (methods/weave/weave_layer.h,
// vertex_pass/visible_vertices.h): the kiosk's frame of a pillow at its close-up, and turned a few
// degrees from there, is the frame with every vertex computed, bit for bit, for a per-vertex rung
// and for `sheen` (whose own draw has no passes, so the weave's are the only ones culled); the
// layer did draw (the frame differs from the weave off); and with culling then switched off, a
// view turned 40° is the every-vertex frame again. And the fabric knob's preset shows its weave at
// its own size.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "bundle/bundle_reader.h"
#include "core/weave_layout.h"
#include "gl/offscreen_target.h"
#include "gpu/egl_context.h"
#include "kiosk/camera_zoom.h"
#include "kiosk/kiosk_bundle.h"
#include "kiosk/kiosk_renderer.h"
#include "methods/vertex_pass/visible_vertices.h"
#include "support/small_bundle.h"

using namespace weft;

namespace {

constexpr int kWidth = 320, kHeight = 240;

Camera turned(const Camera& c, double deg) {
  Camera out = c;
  const glm::dmat4 r = glm::rotate(glm::dmat4(1.0), glm::radians(deg), glm::dvec3(0, 0, 1));
  out.position = glm::dvec3(r * glm::dvec4(c.position - c.target, 0.0)) + c.target;
  return out;
}

}  // namespace

TEST(WeaveCulling, VisibleVerticesOnlyDrawTheSameFrame) {
  const test::SmallBundle small("pillow");
  ASSERT_TRUE(small.baked()) << "bake failed; see " << small.dir() / "bake.log";
  gpu::EglContext ctx = gpu::EglContext::headless();
  if (!gpu::VisibleVertices::supported()) GTEST_SKIP() << "no GLES 3.2: every vertex is computed";
  const bundle::BundleReader reader = bundle::BundleReader::open(small.file());
  for (const std::string name : {"iwasaki_vertex", "sheen"}) {
    SCOPED_TRACE(name);
    const KioskBundle kb = read_kiosk_bundle(reader, name);
    const methods::RuntimeMethod& method = kiosk_method(name, kb, small.file());
    const std::vector<Fabric> cloth = cloth_fabrics(kb.scene);
    const Camera closeup = closeup_of(kb.scene.scene, cloth, kHeight);
    auto renderer = [&](bool visible_only) {
      std::unique_ptr<gpu::SceneRenderer> r = make_kiosk_renderer(kb.scene, cloth, method, kb.shading);
      r->set_lighting(kb.scene.sgs);
      r->set_visible_vertices_only(visible_only);
      return r;
    };
    std::unique_ptr<gpu::SceneRenderer> culled = renderer(true), full = renderer(false), plain = renderer(true);
    ASSERT_TRUE(culled->weave()) << "the kiosk's renderer arms the weave layer";
    plain->set_weave(false);
    gpu::OffscreenTarget a(kWidth, kHeight), b(kWidth, kHeight), c(kWidth, kHeight);
    for (double deg : {0.0, 4.0}) {
      SCOPED_TRACE(deg);
      const Camera cam = turned(closeup, deg);
      a.bind();
      culled->draw(cam, kWidth, kHeight);
      b.bind();
      full->draw(cam, kWidth, kHeight);
      c.bind();
      plain->draw(cam, kWidth, kHeight);
      const std::vector<float> pa = a.read_rgba(), pb = b.read_rgba(), pc = c.read_rgba();
      size_t differ = 0, weave = 0;
      for (size_t i = 0; i < pa.size(); ++i) {
        differ += pa[i] != pb[i] ? 1 : 0;
        weave += pa[i] != pc[i] ? 1 : 0;
      }
      EXPECT_EQ(differ, 0u) << "channels that differ from the every-vertex frame";
      EXPECT_GT(weave, 1000u) << "the weave layer drew over too little of the frame to test anything";
    }
    // Culling switched off after culled frames: every vertex again, none kept from the last view.
    culled->set_visible_vertices_only(false);
    const Camera far_turn = turned(closeup, 40.0);
    a.bind();
    culled->draw(far_turn, kWidth, kHeight);
    b.bind();
    full->draw(far_turn, kWidth, kHeight);
    EXPECT_TRUE(a.read_rgba() == b.read_rgba()) << "culling off: the frame is not the every-vertex one";
  }
}

// The fabric knob turned to a preset of another repeat: the layer draws its threads at that
// preset's own size, as a renderer made with it does (the weave coordinates follow the knob).
TEST(WeaveKnob, AnotherPresetsThreadsAtTheirOwnSize) {
  const test::SmallBundle small("pillow");
  ASSERT_TRUE(small.baked()) << "bake failed; see " << small.dir() / "bake.log";
  gpu::EglContext ctx = gpu::EglContext::headless();
  const bundle::BundleReader reader = bundle::BundleReader::open(small.file());
  const KioskBundle kb = read_kiosk_bundle(reader, "sheen");
  const methods::RuntimeMethod& method = kiosk_method("sheen", kb, small.file());
  const std::vector<Fabric> cloth = cloth_fabrics(kb.scene);
  ASSERT_EQ(cloth.size(), 1u);
  const std::string other = cloth[0].name == "velvet" ? "linen_plain" : "velvet";
  const Fabric turned_to = load_fabric_preset(other, std::filesystem::path(WEFT_SOURCE_ASSETS) / "fabrics");
  ASSERT_GT(glm::length(weave_repeat_cm(turned_to) - weave_repeat_cm(cloth[0])), 0.05 * glm::length(weave_repeat_cm(cloth[0])))
      << "the two presets must differ in repeat for this to test anything";
  const Camera closeup = closeup_of(kb.scene.scene, cloth, kHeight);
  std::unique_ptr<gpu::SceneRenderer> knob = make_kiosk_renderer(kb.scene, cloth, method, kb.shading);
  std::unique_ptr<gpu::SceneRenderer> fresh = make_kiosk_renderer(kb.scene, {turned_to}, method, kb.shading);
  std::unique_ptr<gpu::SceneRenderer> before = make_kiosk_renderer(kb.scene, cloth, method, kb.shading);
  for (auto* r : {knob.get(), fresh.get(), before.get()}) r->set_lighting(kb.scene.sgs);
  gpu::OffscreenTarget a(kWidth, kHeight), b(kWidth, kHeight), c(kWidth, kHeight);
  a.bind();
  knob->draw(closeup, kWidth, kHeight);  // the first preset's frame, then the knob
  knob->set_fabric(0, turned_to);
  a.bind();
  knob->draw(closeup, kWidth, kHeight);
  b.bind();
  fresh->draw(closeup, kWidth, kHeight);
  c.bind();
  before->draw(closeup, kWidth, kHeight);
  const std::vector<float> pa = a.read_rgba(), pb = b.read_rgba(), pc = c.read_rgba();
  double worst = 0.0;
  size_t changed = 0;
  for (size_t i = 0; i < pa.size(); ++i) {
    worst = std::max(worst, double(std::abs(pa[i] - pb[i])));
    changed += std::abs(pa[i] - pc[i]) > 1e-3f ? 1 : 0;
  }
  EXPECT_LE(worst, 1e-4) << "the knob's frame differs from a renderer made with " << other;
  EXPECT_GT(changed, 1000u) << "the knob changed too little of the close-up to test anything";
}
