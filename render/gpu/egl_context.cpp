#include "gpu/egl_context.h"

#include <GLES3/gl3.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace weft::gpu {

namespace {

std::string egl_error_name(EGLint e) {
  switch (e) {
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_NATIVE_WINDOW: return "EGL_BAD_NATIVE_WINDOW";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE: return "EGL_BAD_SURFACE";
    default: return "EGL error " + std::to_string(e);
  }
}

[[noreturn]] void fail(const std::string& what) { throw GpuError(what + ": " + egl_error_name(eglGetError())); }

bool has_extension(const char* list, const char* name) {
  if (!list) return false;
  const size_t n = std::strlen(name);
  for (const char* p = list; (p = std::strstr(p, name)); p += n)
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  return false;
}

EGLDisplay open_headless_display() {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  auto get_platform_display =
      reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (!get_platform_display) throw GpuError("EGL has no eglGetPlatformDisplayEXT (EGL_EXT_platform_base)");
  // Prefer a real GPU through the device platform (NVIDIA's EGL offers it), then Mesa's
  // surfaceless platform (llvmpipe or a render node).
  if (has_extension(client, "EGL_EXT_platform_device")) {
    auto query_devices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    EGLDeviceEXT devices[8];
    EGLint count = 0;
    if (query_devices && query_devices(8, devices, &count)) {
      for (EGLint i = 0; i < count; ++i) {
        EGLDisplay d = get_platform_display(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
        EGLint major, minor;
        if (d != EGL_NO_DISPLAY && eglInitialize(d, &major, &minor)) {
          const char* vendor = eglQueryString(d, EGL_VENDOR);
          // Mesa exposes a software device here too; leave that to the surfaceless path.
          if (vendor && std::strstr(vendor, "Mesa") == nullptr) return d;
          eglTerminate(d);
        }
      }
    }
  }
  if (has_extension(client, "EGL_MESA_platform_surfaceless")) {
    EGLDisplay d = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    EGLint major, minor;
    if (d != EGL_NO_DISPLAY && eglInitialize(d, &major, &minor)) return d;
  }
  throw GpuError("no headless EGL display: neither an EGL device nor EGL_MESA_platform_surfaceless works "
                 "(install libegl-mesa0 and libgl1-mesa-dri)");
}

EGLContext create_gles3_context(EGLDisplay display, EGLConfig config) {
  if (!eglBindAPI(EGL_OPENGL_ES_API)) fail("eglBindAPI(OpenGL ES)");
  const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 0, EGL_NONE};
  EGLContext c = eglCreateContext(display, config, EGL_NO_CONTEXT, attribs);
  if (c == EGL_NO_CONTEXT) fail("eglCreateContext(OpenGL ES 3.0)");
  return c;
}

}  // namespace

EglContext EglContext::headless() {
  EglContext ctx;
  ctx.display_ = open_headless_display();
  const char* ext = eglQueryString(ctx.display_, EGL_EXTENSIONS);
  EGLConfig config = EGL_NO_CONFIG_KHR;
  if (!has_extension(ext, "EGL_KHR_no_config_context")) {
    const EGLint want[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_ES3_BIT, EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_NONE};
    EGLint n = 0;
    if (!eglChooseConfig(ctx.display_, want, &config, 1, &n) || n < 1) fail("eglChooseConfig(ES3, pbuffer)");
  }
  ctx.context_ = create_gles3_context(ctx.display_, config);
  ctx.make_current();
  return ctx;
}

EglContext EglContext::on_gbm(gbm_device* device, unsigned format) {
  EglContext ctx;
  auto get_platform_display =
      reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (!get_platform_display) throw GpuError("EGL has no eglGetPlatformDisplayEXT");
  ctx.display_ = get_platform_display(EGL_PLATFORM_GBM_KHR, device, nullptr);
  EGLint major, minor;
  if (ctx.display_ == EGL_NO_DISPLAY || !eglInitialize(ctx.display_, &major, &minor)) fail("EGL on GBM");
  // Without a screen the context stays current with no surface at all.
  if (!has_extension(eglQueryString(ctx.display_, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context"))
    throw GpuError("EGL on GBM lacks EGL_KHR_surfaceless_context (needed to keep drawing while no screen is connected)");
  const EGLint want[] = {EGL_SURFACE_TYPE, EGL_WINDOW_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_ES3_BIT,
                         EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_NONE};
  EGLint n = 0;
  eglChooseConfig(ctx.display_, want, nullptr, 0, &n);
  std::vector<EGLConfig> configs(n);
  if (n < 1 || !eglChooseConfig(ctx.display_, want, configs.data(), n, &n)) fail("eglChooseConfig(ES3, window)");
  // The scan-out format must match the config's native visual exactly. The context is made with
  // this config, so every later window surface (one per screen connected) is compatible with it.
  for (EGLConfig c : configs) {
    EGLint id = 0;
    if (eglGetConfigAttrib(ctx.display_, c, EGL_NATIVE_VISUAL_ID, &id) && static_cast<unsigned>(id) == format) {
      ctx.config_ = c;
      break;
    }
  }
  if (!ctx.config_) throw GpuError("no EGL config matches the scan-out format");
  ctx.context_ = create_gles3_context(ctx.display_, ctx.config_);
  ctx.make_current();
  return ctx;
}

void EglContext::attach_window(gbm_surface* surface) {
  detach_window();
  surface_ = eglCreateWindowSurface(display_, config_, reinterpret_cast<EGLNativeWindowType>(surface), nullptr);
  if (surface_ == EGL_NO_SURFACE) fail("eglCreateWindowSurface(GBM)");
  make_current();
}

void EglContext::detach_window() {
  if (surface_ == EGL_NO_SURFACE) return;
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_);
  eglDestroySurface(display_, surface_);
  surface_ = EGL_NO_SURFACE;
}

EglContext::EglContext(EglContext&& o) noexcept
    : display_(o.display_), context_(o.context_), surface_(o.surface_), config_(o.config_) {
  o.display_ = EGL_NO_DISPLAY;
  o.context_ = EGL_NO_CONTEXT;
  o.surface_ = EGL_NO_SURFACE;
}

EglContext::~EglContext() {
  if (display_ == EGL_NO_DISPLAY) return;
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  if (surface_ != EGL_NO_SURFACE) eglDestroySurface(display_, surface_);
  if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
  eglTerminate(display_);
}

void EglContext::make_current() const {
  if (!eglMakeCurrent(display_, surface_, surface_, context_)) fail("eglMakeCurrent");
}

void EglContext::swap_buffers() const {
  if (surface_ != EGL_NO_SURFACE && !eglSwapBuffers(display_, surface_)) fail("eglSwapBuffers");
}

std::string EglContext::renderer() const { return reinterpret_cast<const char*>(glGetString(GL_RENDERER)); }
std::string EglContext::version() const { return reinterpret_cast<const char*>(glGetString(GL_VERSION)); }

bool EglContext::has_gl_extension(const char* name) const {
  GLint n = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &n);
  for (GLint i = 0; i < n; ++i)
    if (std::strcmp(reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, i)), name) == 0) return true;
  return false;
}

TimerQueryFunctions timer_query_functions() {
  GLint n = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &n);
  bool has = false;
  for (GLint i = 0; i < n && !has; ++i)
    has = std::strcmp(reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, i)), "GL_EXT_disjoint_timer_query") == 0;
  if (!has) return {};
  TimerQueryFunctions f;
  f.query_counter = reinterpret_cast<void (*)(GLuint, GLenum)>(eglGetProcAddress("glQueryCounterEXT"));
  f.get_query_object_ui64 = reinterpret_cast<void (*)(GLuint, GLenum, GLuint64*)>(eglGetProcAddress("glGetQueryObjectui64vEXT"));
  return f;
}

bool software_renderer() {
  const auto* r = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const std::string name = r ? r : "";
  return name.find("llvmpipe") != std::string::npos || name.find("softpipe") != std::string::npos;
}

}  // namespace weft::gpu
