// output movie FILE ?-every K? ?-fps n? ?view options?: frames piped to ffmpeg
// while runs go on. The movie is written under a temporary name and appears
// whole, under its own name, when the recorder is closed.
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include "output_verbs.hpp"
#include "sandflow/render/scene_builder.hpp"
#include "sandflow/tcl/args.hpp"
#include "sandflow/tcl/picture.hpp"
#include "sandflow/tcl/session.hpp"

extern char** environ;

namespace sf::tcl {
namespace {

const char* const kContainers[] = {".mp4", ".mkv", ".mov", ".avi", ".webm"};

std::string lowerExtension(const std::string& path) {
  const auto dot = path.rfind('.');
  const auto slash = path.rfind('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return ext;
}

// ffmpeg's full path from $PATH, or "" when it is not installed.
std::string findFfmpeg() {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "/usr/bin:/bin");
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    const std::string candidate = (dir.empty() ? "." : dir) + "/ffmpeg";
    if (access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return "";
}

std::string tail(const std::string& file, std::size_t max) {
  std::ifstream in(file);
  std::stringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  return text.size() > max ? "..." + text.substr(text.size() - max) : text;
}

class MovieRecorder final : public Recorder {
 public:
  MovieRecorder(std::string path, int every, int fps, render::ViewOptions view)
      : Recorder(std::move(path), every), fps_(fps), view_(std::move(view)) {}
  ~MovieRecorder() override { stop(); }

  // Starts ffmpeg writing to a temporary file beside the movie.
  void start(const std::string& ffmpeg) {
    const std::string& p = path();
    const auto slash = p.rfind('/');
    const std::string dir = slash == std::string::npos ? "." : p.substr(0, slash);
    const std::string name = slash == std::string::npos ? p : p.substr(slash + 1);
    partial_ = dir + "/." + name + ".part" + lowerExtension(p);
    log_ = dir + "/." + name + ".ffmpeg.log";
    // Creating the part file ourselves tells an unwritable folder at once.
    const int probe = open(partial_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (probe < 0) throw Error("IO MOVIE", "cannot write " + p + ": " + std::strerror(errno));
    close(probe);
    int fds[2];
    if (pipe2(fds, O_CLOEXEC) != 0) {
      const int e = errno;
      std::remove(partial_.c_str());
      throw Error("IO MOVIE", std::string("no pipe: ") + std::strerror(e));
    }
    const std::string size = std::to_string(view_.width) + "x" + std::to_string(view_.height);
    const std::string rate = std::to_string(fps_);
    // yuv420p (what players expect) needs even sides: pad by one pixel if odd.
    std::vector<std::string> args = {ffmpeg,      "-nostdin", "-hide_banner",
                                     "-loglevel", "error",    "-y",
                                     "-f",        "rawvideo", "-pix_fmt",
                                     "rgba",      "-s",       size,
                                     "-r",        rate,       "-i",
                                     "-",         "-vf",      "pad=ceil(iw/2)*2:ceil(ih/2)*2",
                                     "-pix_fmt",  "yuv420p",  partial_};
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[0], 0);
    posix_spawn_file_actions_addclose(&actions, fds[0]);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, log_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int rc = posix_spawn(&child_, ffmpeg.c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    close(fds[0]);
    if (rc != 0) {
      close(fds[1]);
      std::remove(partial_.c_str());
      std::remove(log_.c_str());
      throw Error("IO MOVIE", "cannot start " + ffmpeg + ": " + std::strerror(rc));
    }
    pipe_ = fds[1];
  }

  const char* kind() const override { return "movie"; }
  void abandon() noexcept override { stop(); }

  void record(const Session& s) override {
    const render::Image frame = takePicture(s.manager, view_);
    if (!writeAll(frame.rgba.data(), frame.rgba.size())) {
      const std::string why = stopAndExplain();
      throw Error("IO MOVIE", "ffmpeg stopped taking frames" + why);
    }
    ++written_;
  }

  void finish() override {
    if (child_ <= 0) return;
    const std::string why = stopAndExplain();
    if (!why.empty()) throw Error("IO MOVIE", "ffmpeg failed" + why);
    if (std::rename(partial_.c_str(), path().c_str()) != 0) {
      const std::string e = std::strerror(errno);
      std::remove(partial_.c_str());
      throw Error("IO MOVIE", "cannot rename the finished movie to " + path() + ": " + e);
    }
  }

 private:
  // Writes without letting a dead ffmpeg's SIGPIPE end the process.
  bool writeAll(const std::uint8_t* data, std::size_t n) {
    sigset_t block, old;
    sigemptyset(&block);
    sigaddset(&block, SIGPIPE);
    pthread_sigmask(SIG_BLOCK, &block, &old);
    bool ok = true;
    while (n > 0) {
      const ssize_t w = write(pipe_, data, n);
      if (w < 0 && errno == EINTR) continue;
      if (w <= 0) {
        ok = false;
        break;
      }
      data += w;
      n -= std::size_t(w);
    }
    if (!ok) {  // take the pending SIGPIPE before unblocking
      const timespec zero{0, 0};
      sigtimedwait(&block, nullptr, &zero);
    }
    pthread_sigmask(SIG_SETMASK, &old, nullptr);
    return ok;
  }

  // Ends ffmpeg; "" if it exited cleanly, else ": <its last message>". The
  // partial file and the log are removed on failure.
  std::string stopAndExplain() {
    if (child_ <= 0) return "";
    if (pipe_ >= 0) close(pipe_);
    pipe_ = -1;
    int status = 0;
    while (waitpid(child_, &status, 0) < 0 && errno == EINTR) {
    }
    child_ = -1;
    const bool ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
    std::string why;
    if (!ok) {
      const std::string said = tail(log_, 400);
      why =
          said.empty() ? " (exit status " + std::to_string(WEXITSTATUS(status)) + ")" : ": " + said;
      std::remove(partial_.c_str());
    }
    std::remove(log_.c_str());
    return why;
  }

  void stop() {
    if (child_ > 0) {
      stopAndExplain();
      std::remove(partial_.c_str());
    }
  }

  int fps_;
  render::ViewOptions view_;
  std::string partial_, log_;
  pid_t child_ = -1;
  int pipe_ = -1;
};

const OptionSpec kMovieOptions[] = {{"-every", "K", "a frame every K steps (default 1)"},
                                    {"-fps", "n", "frames per second of the movie (default 25)"},
                                    {nullptr, nullptr, nullptr}};

}  // namespace

int OutputMovie(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc < 2) {
    Tcl_WrongNumArgs(interp, 1, objv, "FILE ?-every K? ?-fps n? ?-option value ...?");
    return TCL_ERROR;
  }
  Session& s = *static_cast<Session*>(data);
  const std::string path = Tcl_GetString(objv[1]);
  const std::string ext = lowerExtension(path);
  if (std::none_of(std::begin(kContainers), std::end(kContainers),
                   [&](const char* c) { return ext == c; }))
    return fail(interp, "VALUE FILE",
                "output movie writes .mp4, .mkv, .mov, .avi or .webm files, got \"" + path + "\"");
  // -every and -fps first, then the view options (which default to view configure's).
  int every = 1, fps = 25;
  std::vector<Tcl_Obj*> viewArgs(objv, objv + 2);
  for (int i = 2; i < objc; i += 2) {
    const std::string name = Tcl_GetString(objv[i]);
    if (name != "-every" && name != "-fps") {
      viewArgs.push_back(objv[i]);
      if (i + 1 < objc) viewArgs.push_back(objv[i + 1]);
      continue;
    }
    if (i + 1 >= objc) return fail(interp, "VALUE MISSING", "value for \"" + name + "\" missing");
    if (name == "-every") {
      if (!getEvery(interp, objv[i + 1], every)) return TCL_ERROR;
      continue;
    }
    if (!getInt(interp, objv[i + 1], "-fps", fps)) return TCL_ERROR;
    if (fps < 1 || fps > 240)
      return fail(interp, "VALUE FPS", "-fps must be 1 to 240, got " + std::to_string(fps));
  }
  render::ViewOptions view = s.view;
  if (!parseViewOptions(interp, int(viewArgs.size()), viewArgs.data(), 2, view, nullptr))
    return TCL_ERROR;
  const std::string ffmpeg = findFfmpeg();
  if (ffmpeg.empty())
    return fail(interp, "RESOURCE FFMPEG",
                "output movie needs ffmpeg, which is not installed (Debian package ffmpeg)");
  if (recording(s, path))  // before ffmpeg starts
    return fail(interp, "VALUE OUTPUT",
                "\"" + path + "\" is already being recorded to; output close it first");
  auto movie = std::make_unique<MovieRecorder>(path, every, fps, view);
  const int code = guarded(interp, [&] {
    render::checkView(s.manager, view);  // before starting ffmpeg
    movie->start(ffmpeg);
    return TCL_OK;
  });
  if (code != TCL_OK) return code;
  if (startRecorder(s, std::move(movie), objc, objv) != TCL_OK) return TCL_ERROR;
  Tcl_SetObjResult(interp, newString(path));
  return TCL_OK;
}

}  // namespace sf::tcl
