// The EGL back end: Mesa's surfaceless platform (no display, no X) with a
// pbuffer of each picture's size, desktop OpenGL in the compatibility profile.
// The fallback for when OSMesa is missing (Mesa 25.1 drops it).
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>

#include <dlfcn.h>

#include <cstdio>

#include "sandflow/render/gl_draw.hpp"
#include "sandflow/render/offscreen_api.hpp"

namespace sf::render {
namespace {

struct Egl {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLConfig config = nullptr;
  EGLContext context = EGL_NO_CONTEXT;
  EGLSurface surface = EGL_NO_SURFACE;
  int width = 0, height = 0;
};
Egl egl;

std::string eglFailure(const char* what) {
  char code[16];
  std::snprintf(code, sizeof code, "0x%04x", unsigned(eglGetError()));
  return std::string("EGL: ") + what + " failed (error " + code + ")";
}

bool initialise(std::string& error) {
  auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (!getPlatformDisplay) {
    error = "EGL: eglGetPlatformDisplayEXT is missing (no EGL_EXT_platform_base)";
    return false;
  }
  egl.display = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  EGLint major = 0, minor = 0;
  if (egl.display == EGL_NO_DISPLAY || !eglInitialize(egl.display, &major, &minor)) {
    error = eglFailure("the surfaceless display");
    return false;
  }
  const EGLint attributes[] = {EGL_SURFACE_TYPE,
                               EGL_PBUFFER_BIT,
                               EGL_RED_SIZE,
                               8,
                               EGL_GREEN_SIZE,
                               8,
                               EGL_BLUE_SIZE,
                               8,
                               EGL_ALPHA_SIZE,
                               8,
                               EGL_RENDERABLE_TYPE,
                               EGL_OPENGL_BIT,
                               EGL_NONE};
  EGLint count = 0;
  if (!eglChooseConfig(egl.display, attributes, &egl.config, 1, &count) || count < 1) {
    error = "EGL: no RGBA8 pbuffer configuration for desktop OpenGL";
    return false;
  }
  if (!eglBindAPI(EGL_OPENGL_API)) {
    error = eglFailure("binding desktop OpenGL");
    return false;
  }
  egl.context = eglCreateContext(egl.display, egl.config, EGL_NO_CONTEXT, nullptr);
  if (egl.context == EGL_NO_CONTEXT) {
    error = eglFailure("creating a context");
    return false;
  }
  return true;
}

bool useSurface(int width, int height, std::string& error) {
  if (egl.surface != EGL_NO_SURFACE && egl.width == width && egl.height == height) return true;
  if (egl.surface != EGL_NO_SURFACE) {
    eglMakeCurrent(egl.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroySurface(egl.display, egl.surface);
    egl.surface = EGL_NO_SURFACE;
  }
  const EGLint size[] = {EGL_WIDTH, width, EGL_HEIGHT, height, EGL_NONE};
  egl.surface = eglCreatePbufferSurface(egl.display, egl.config, size);
  if (egl.surface == EGL_NO_SURFACE) {
    error = eglFailure(
        ("a " + std::to_string(width) + " x " + std::to_string(height) + " pbuffer").c_str());
    return false;
  }
  egl.width = width;
  egl.height = height;
  return true;
}

// In the workbench a GLX context (Togl's view) may be current on this thread,
// and GLVND refuses to make an EGL context current over another API's
// (EGL_BAD_ACCESS). This releases it for the picture and restores it after,
// through libGLX if the process has loaded it (this module does not link it).
class GlxReleased {
 public:
  GlxReleased() {
    handle_ = dlopen("libGLX.so.0", RTLD_LAZY | RTLD_NOLOAD);
    if (!handle_) return;
    const auto currentContext =
        reinterpret_cast<void* (*)()>(dlsym(handle_, "glXGetCurrentContext"));
    const auto currentDisplay =
        reinterpret_cast<void* (*)()>(dlsym(handle_, "glXGetCurrentDisplay"));
    const auto currentDrawable =
        reinterpret_cast<unsigned long (*)()>(dlsym(handle_, "glXGetCurrentDrawable"));
    makeCurrent_ =
        reinterpret_cast<int (*)(void*, unsigned long, void*)>(dlsym(handle_, "glXMakeCurrent"));
    if (!currentContext || !currentDisplay || !currentDrawable || !makeCurrent_) return;
    context_ = currentContext();
    if (!context_) return;
    display_ = currentDisplay();
    drawable_ = currentDrawable();
    makeCurrent_(display_, 0, nullptr);
  }
  ~GlxReleased() {
    if (context_) {
      eglMakeCurrent(egl.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
      makeCurrent_(display_, drawable_, context_);
    }
    if (handle_) dlclose(handle_);
  }
  GlxReleased(const GlxReleased&) = delete;
  GlxReleased& operator=(const GlxReleased&) = delete;

 private:
  void* handle_ = nullptr;
  int (*makeCurrent_)(void*, unsigned long, void*) = nullptr;
  void* display_ = nullptr;
  unsigned long drawable_ = 0;
  void* context_ = nullptr;
};

bool renderEgl(const DrawList& list, Image& out, std::string& error) {
  if (egl.context == EGL_NO_CONTEXT && !initialise(error)) return false;
  if (!useSurface(list.width, list.height, error)) return false;
  const GlxReleased released;
  if (!eglMakeCurrent(egl.display, egl.surface, egl.surface, egl.context)) {
    error = eglFailure("making the context current");
    return false;
  }
  drawList(list);
  std::vector<std::uint8_t> buffer(std::size_t(list.width) * list.height * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, list.width, list.height, GL_RGBA, GL_UNSIGNED_BYTE, buffer.data());
  imageFromBuffer(buffer, list.width, list.height, out);
  return true;
}

const OffscreenApi api{kOffscreenApiVersion, "egl", renderEgl, drawList};

}  // namespace
}  // namespace sf::render

extern "C" __attribute__((visibility("default"))) const sf::render::OffscreenApi*
sandflow_offscreen_api() {
  return &sf::render::api;
}
