// Every GL program the kiosk makes fits the uniform storage of the drivers a showroom runs on.
// NVIDIA's GLSL compiler gives a program's default uniform block 1024 registers of four
// components and each element of a uniform array a register of its own, whatever its type
// (an H200 refused the iwasaki programs with "error C6020: Constant register limit exceeded ...
// more than 1024 registers needed", when four 128-element scalar tables and a 512-element ivec2
// index sat in them). llvmpipe packs tighter and accepts far more, so this counts the registers
// the NVIDIA way over every program alive after each kiosk rung has drawn a pillow from its
// scene camera and from its close-up (where the weave layer draws too).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "bundle/bundle_reader.h"
#include "gl/offscreen_target.h"
#include "gpu/egl_context.h"
#include "kiosk/camera_zoom.h"
#include "kiosk/kiosk_bundle.h"
#include "kiosk/kiosk_renderer.h"
#include "methods/registry.h"
#include "support/small_bundle.h"

using namespace weft;

namespace {

constexpr int kNvidiaRegisters = 1024;

// Registers of a program's default uniform block counted as NVIDIA's compiler counts them: one per
// element of each active uniform (a matrix one per column), samplers included.
struct Budget {
  int registers = 0;
  std::string largest;  // its largest uniform, for the message
  int largest_registers = 0;
};

int columns(GLenum type) {
  switch (type) {
    case GL_FLOAT_MAT2: case GL_FLOAT_MAT2x3: case GL_FLOAT_MAT2x4: return 2;
    case GL_FLOAT_MAT3: case GL_FLOAT_MAT3x2: case GL_FLOAT_MAT3x4: return 3;
    case GL_FLOAT_MAT4: case GL_FLOAT_MAT4x2: case GL_FLOAT_MAT4x3: return 4;
    default: return 1;
  }
}

Budget budget(GLuint program) {
  Budget b;
  GLint count = 0;
  glGetProgramiv(program, GL_ACTIVE_UNIFORMS, &count);
  for (GLuint i = 0; i < GLuint(count); ++i) {
    GLint block = -1;
    glGetActiveUniformsiv(program, 1, &i, GL_UNIFORM_BLOCK_INDEX, &block);
    if (block != -1) continue;  // a uniform buffer's member: not in the default block
    char name[256];
    GLint size = 0;
    GLenum type = 0;
    glGetActiveUniform(program, i, sizeof name, nullptr, &size, &type, name);
    const int r = size * columns(type);
    b.registers += r;
    if (r > b.largest_registers) b.largest_registers = r, b.largest = name;
  }
  return b;
}

// Every linked program object of the current context (program names are small integers).
std::vector<GLuint> linked_programs() {
  std::vector<GLuint> out;
  for (GLuint id = 1; id < 4096; ++id) {
    if (!glIsProgram(id)) continue;
    GLint linked = GL_FALSE;
    glGetProgramiv(id, GL_LINK_STATUS, &linked);
    if (linked) out.push_back(id);
  }
  return out;
}

}  // namespace

TEST(UniformBudget, EveryKioskProgramFitsNvidiasRegisters) {
  const test::SmallBundle small("pillow");
  ASSERT_TRUE(small.baked()) << "bake failed; see " << small.dir() / "bake.log";
  gpu::EglContext ctx = gpu::EglContext::headless();
  const bundle::BundleReader reader = bundle::BundleReader::open(small.file());
  constexpr int kWidth = 160, kHeight = 120;
  gpu::OffscreenTarget target(kWidth, kHeight);
  int rungs = 0, programs = 0, most = 0;
  for (const methods::RuntimeMethod& m : methods::registry()) {
    if (!m.kiosk_rung) continue;
    SCOPED_TRACE(m.name);
    const KioskBundle kb = read_kiosk_bundle(reader, m.name);
    const methods::RuntimeMethod& method = kiosk_method(m.name, kb, small.file());
    const std::vector<Fabric> cloth = cloth_fabrics(kb.scene);
    std::unique_ptr<gpu::SceneRenderer> r = make_kiosk_renderer(kb.scene, cloth, method, kb.shading);
    r->set_lighting(kb.scene.sgs);
    target.bind();
    r->draw(kb.scene.scene.camera, kWidth, kHeight);
    r->draw(closeup_of(kb.scene.scene, cloth, kHeight), kWidth, kHeight);
    glFinish();
    ++rungs;
    for (GLuint p : linked_programs()) {
      const Budget b = budget(p);
      EXPECT_LE(b.registers, kNvidiaRegisters) << "program " << p << " of " << m.name << " needs " << b.registers
                                               << " registers; its largest uniform " << b.largest << " takes "
                                               << b.largest_registers;
      most = std::max(most, b.registers);
      ++programs;
    }
  }
  EXPECT_GE(rungs, 4) << "the registry's kiosk rungs";
  EXPECT_GT(programs, rungs) << "no programs found: the count would pass anything";
  std::printf("%d kiosk rungs, %d programs checked; the largest needs %d of %d registers\n", rungs, programs, most,
              kNvidiaRegisters);
}
