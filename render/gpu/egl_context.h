#pragma once
// An OpenGL ES 3 context through EGL. Two ways in: headless (Mesa's surfaceless platform, else
// the EGL device platform, rendering only to FBOs) and on a GBM device (the kiosk's DRM/KMS
// scan-out, see kms_display.h), where a window surface comes and goes with the screen while the
// context, and every GL object made in it, stays.
#include <string>

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include "gl/frame_profile.h"
#include "gl/gl_error.h"

struct gbm_device;
struct gbm_surface;

namespace weft::gpu {

class EglContext {
public:
  // Headless: no window system, no display. Throws GpuError saying what is missing.
  static EglContext headless();
  // On a GBM device, current without a surface (EGL_KHR_surfaceless_context: FBOs only) until
  // attach_window; its config renders into scan-out buffers of `format` (a GBM fourcc).
  static EglContext on_gbm(gbm_device* device, unsigned format);
  // A window surface on `surface` (a gbm_surface of the format above), made current.
  void attach_window(gbm_surface* surface);
  // Current again without a surface; the window surface destroyed. A no-op without one.
  void detach_window();
  bool has_window() const { return surface_ != EGL_NO_SURFACE; }

  EglContext(EglContext&& o) noexcept;
  EglContext& operator=(EglContext&&) = delete;
  EglContext(const EglContext&) = delete;
  ~EglContext();

  void make_current() const;
  // Presents the window surface (GBM only); a no-op headless.
  void swap_buffers() const;

  std::string renderer() const;  // GL_RENDERER
  std::string version() const;   // GL_VERSION
  bool has_gl_extension(const char* name) const;
  EGLDisplay display() const { return display_; }

private:
  EglContext() = default;
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
  EGLSurface surface_ = EGL_NO_SURFACE;
  EGLConfig config_ = nullptr;  // GBM: the window surfaces' config, the context's too
};

// The current context's timer queries (EXT_disjoint_timer_query), all null where it has none.
TimerQueryFunctions timer_query_functions();
// The current context renders on the CPU (Mesa's llvmpipe or softpipe): its timer queries stamp
// commands as they are queued, not as they run, so a profile there times on the CPU clock.
bool software_renderer();

}  // namespace weft::gpu
