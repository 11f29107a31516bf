// output movie FILE ?-every K? ?-fps n? ?view options?: frames piped to ffmpeg
// while runs go on. The movie is written under a temporary name and appears
// whole, under its own name, when the recorder is closed.
#include <memory>
#include <string>
#include <vector>

#include "output_verbs.hpp"
#include "sandflow/io/ffmpeg_pipe.hpp"
#include "sandflow/io/find_program.hpp"
#include "sandflow/render/scene_builder.hpp"
#include "sandflow/tcl/args.hpp"
#include "sandflow/tcl/picture.hpp"
#include "sandflow/tcl/session.hpp"

namespace sf::tcl {
namespace {

// Takes the pictures; the encoding is io::FfmpegPipe's.
class MovieRecorder final : public Recorder {
 public:
  MovieRecorder(std::string path, int every, int fps, render::ViewOptions view)
      : Recorder(std::move(path), every), fps_(fps), view_(std::move(view)) {}

  void start(const std::string& ffmpeg) {
    pipe_ = std::make_unique<io::FfmpegPipe>(ffmpeg, path(), view_.width, view_.height, fps_);
  }

  const char* kind() const override { return "movie"; }
  void abandon() noexcept override { pipe_.reset(); }  // removes what ffmpeg began

  void record(const Session& s) override {
    const render::Image frame = takePicture(s.manager, view_);
    pipe_->writeFrame(frame.rgba.data(), frame.rgba.size());
    ++written_;
  }

  void finish() override {
    if (pipe_) pipe_->finish();
  }

 private:
  int fps_;
  render::ViewOptions view_;
  std::unique_ptr<io::FfmpegPipe> pipe_;
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
  if (!io::isMovieFile(path))
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
  const std::string ffmpeg = io::findProgram("ffmpeg");
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
