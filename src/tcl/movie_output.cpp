// output movie FILE ?-every K? ?-fps n? ?view options?: frames piped to ffmpeg
// while runs go on. The movie is written under a temporary name and appears
// whole, under its own name, when the recorder is closed.
#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "output_verbs.hpp"
#include "sandflow/io/ffmpeg_pipe.hpp"
#include "sandflow/io/find_program.hpp"
#include "sandflow/render/scene_builder.hpp"
#include "sandflow/tcl/args.hpp"
#include "sandflow/tcl/option_table.hpp"
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

// What output movie is asked besides the file and the view options.
struct MovieDraft {
  int every = 1, fps = 25;
};
const OptionTable<MovieDraft> kMovieOptions{
    everyRow("a frame every K steps", &MovieDraft::every),
    memberRow({.name = "-fps",
               .synopsis = "n",
               .help = "frames per second of the movie",
               .range = {.min = 1, .max = 240}},
              &MovieDraft::fps),
};

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
  // The movie's own options first, then the view options (which default to
  // view configure's).
  std::vector<Tcl_Obj*> movieArgs(objv, objv + 2), viewArgs(objv, objv + 2);
  for (int i = 2; i < objc; i += 2) {
    std::vector<Tcl_Obj*>& args =
        kMovieOptions.find(Tcl_GetString(objv[i])) >= 0 ? movieArgs : viewArgs;
    args.insert(args.end(), objv + i, objv + std::min(i + 2, objc));
  }
  MovieDraft draft;
  if (!kMovieOptions.apply(interp, int(movieArgs.size()), movieArgs.data(), 2, draft))
    return TCL_ERROR;
  const int every = draft.every, fps = draft.fps;
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

std::string outputMovieOptions() {
  return kMovieOptions.help("output movie", {}, MovieDraft{});
}

}  // namespace sf::tcl
