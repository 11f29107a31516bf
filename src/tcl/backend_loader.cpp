// Loading the off-screen back-end module (render/offscreen_api.hpp) and taking
// pictures with it. Its state is the process's: one back end, loaded once, whose
// one GL context serves every interpreter in turn.
#include <dlfcn.h>

#include <cstdlib>
#include <mutex>
#include <vector>

#include "sandflow/core/error.hpp"
#include "sandflow/render/offscreen_api.hpp"
#include "sandflow/render/scene_builder.hpp"
#include "sandflow/tcl/picture.hpp"

namespace sf::tcl {
namespace {

// Supersampling: each picture is drawn at twice its size and averaged down,
// which antialiases element edges and text in every back end alike.
constexpr int kSupersample = 2;

std::string choice = "auto";
const render::OffscreenApi* api = nullptr;
std::mutex loadMutex;
// The back end's one context serves one picture at a time (interpreters in
// several threads each have a session, but share the process's context).
std::mutex renderMutex;

std::string directoryOf(const std::string& path) {
  const auto slash = path.rfind('/');
  return slash == std::string::npos ? "." : path.substr(0, slash);
}

// Where the modules may be: $SANDFLOW_RENDER_DIR, beside this code (the
// package's folder), under it (the build tree's application), where they
// were built and where they are installed.
std::vector<std::string> moduleFolders() {
  std::vector<std::string> dirs;
  if (const char* env = std::getenv("SANDFLOW_RENDER_DIR"); env && *env) dirs.push_back(env);
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&moduleFolders), &info) && info.dli_fname) {
    const std::string here = directoryOf(info.dli_fname);
    dirs.push_back(here);
    dirs.push_back(here + "/lib/sandflow");
  }
  dirs.push_back(SANDFLOW_MODULE_DIR);
  dirs.push_back(SANDFLOW_INSTALL_MODULE_DIR);
  return dirs;
}

const render::OffscreenApi* tryLoad(const std::string& name, std::string& why) {
  for (const std::string& dir : moduleFolders()) {
    const std::string path = dir + "/libsandflow_" + name + ".so";
    // RTLD_LOCAL: the module's gl* symbols stay its own.
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      const char* e = dlerror();
      // A module that is there but cannot load (its GL library missing) is worth reporting.
      if (e && std::string(e).find("No such file") == std::string::npos)
        why += "\n  " + path + ": " + e;
      continue;
    }
    auto entry =
        reinterpret_cast<const render::OffscreenApi* (*)()>(dlsym(handle, render::kOffscreenEntry));
    const render::OffscreenApi* a = entry ? entry() : nullptr;
    if (!a || a->version != render::kOffscreenApiVersion) {
      why += "\n  " + path + ": not a sandflow back end of this version";
      dlclose(handle);
      continue;
    }
    return a;  // stays loaded for the life of the process
  }
  why += "\n  no libsandflow_" + name + ".so found";
  return nullptr;
}

const render::OffscreenApi& backEnd() {
  std::lock_guard lock(loadMutex);
  if (api) return *api;
  std::string why;
  const std::vector<std::string> order = choice == "auto"
                                             ? std::vector<std::string>{"osmesa", "egl"}
                                             : std::vector<std::string>{choice};
  for (const std::string& name : order)
    if ((api = tryLoad(name, why))) return *api;
  throw Error("RESOURCE OFFSCREEN",
              "no off-screen OpenGL back end could be loaded (" + choice + "):" + why);
}

}  // namespace

std::string offscreenChoice() {
  std::lock_guard lock(loadMutex);
  return choice;
}

void setOffscreenChoice(const std::string& c) {
  std::lock_guard lock(loadMutex);
  if (api && c != choice && c != api->name)
    throw Error("VALUE OFFSCREEN", std::string("this process already draws with ") + api->name +
                                       "; a process loads one OpenGL library only (start a new "
                                       "sandflow to use " +
                                       c + ")");
  choice = c;
}

std::string loadedOffscreen() {
  std::lock_guard lock(loadMutex);
  return api ? api->name : "";
}

render::Image renderOffscreen(const render::DrawList& list) {
  const render::OffscreenApi& b = backEnd();
  render::Image image;
  std::string error;
  std::lock_guard lock(renderMutex);
  if (!b.render(list, image, error)) throw Error("RESOURCE OFFSCREEN", error);
  return image;
}

render::Image takePicture(const sim::Manager& m, const render::ViewOptions& v) {
  static_assert(kSupersample == 2, "render::halve averages 2 x 2 blocks");
  return render::halve(renderOffscreen(render::buildScene(m, v, kSupersample)));
}

void drawIntoCurrentContext(const render::DrawList& list) {
  const render::OffscreenApi& b = backEnd();
  if (!b.drawCurrent)
    throw Error("RESOURCE OFFSCREEN", std::string("the ") + b.name +
                                          " back end cannot draw into the view's OpenGL context "
                                          "(the workbench draws with egl)");
  std::lock_guard lock(renderMutex);
  b.drawCurrent(list);
}

}  // namespace sf::tcl
