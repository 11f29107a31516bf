#include "sandflow/io/ffmpeg_pipe.hpp"

#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

#include "sandflow/core/error.hpp"

extern char** environ;

namespace sf::io {
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

// The end of a file's text, at most `max` characters, without trailing blanks.
std::string tail(const std::string& file, std::size_t max) {
  std::ifstream in(file);
  std::stringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  return text.size() > max ? "..." + text.substr(text.size() - max) : text;
}

}  // namespace

bool isMovieFile(const std::string& path) {
  const std::string ext = lowerExtension(path);
  return std::any_of(std::begin(kContainers), std::end(kContainers),
                     [&](const char* c) { return ext == c; });
}

FfmpegPipe::FfmpegPipe(const std::string& ffmpeg, std::string path, int width, int height, int fps)
    : path_(std::move(path)) {
  const auto slash = path_.rfind('/');
  const std::string dir = slash == std::string::npos ? "." : path_.substr(0, slash);
  const std::string name = slash == std::string::npos ? path_ : path_.substr(slash + 1);
  partial_ = dir + "/." + name + ".part" + lowerExtension(path_);
  log_ = dir + "/." + name + ".ffmpeg.log";
  // Creating the part file ourselves tells an unwritable folder at once.
  const int probe = ::open(partial_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (probe < 0) throw Error("IO MOVIE", "cannot write " + path_ + ": " + std::strerror(errno));
  ::close(probe);
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) {
    const int e = errno;
    std::remove(partial_.c_str());
    throw Error("IO MOVIE", std::string("no pipe: ") + std::strerror(e));
  }
  const std::string size = std::to_string(width) + "x" + std::to_string(height);
  const std::string rate = std::to_string(fps);
  // yuv420p (what players expect) needs even sides: pad by one pixel if odd.
  std::vector<std::string> args = {
      ffmpeg,     "-nostdin", "-hide_banner", "-loglevel", "error", "-y",
      "-f",       "rawvideo", "-pix_fmt",     "rgba",      "-s",    size,
      "-r",       rate,       "-i",           "-",         "-vf",   "pad=ceil(iw/2)*2:ceil(ih/2)*2",
      "-pix_fmt", "yuv420p",  partial_};
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
  ::close(fds[0]);
  if (rc != 0) {
    child_ = -1;
    ::close(fds[1]);
    std::remove(partial_.c_str());
    std::remove(log_.c_str());
    throw Error("IO MOVIE", "cannot start " + ffmpeg + ": " + std::strerror(rc));
  }
  pipe_ = fds[1];
}

void FfmpegPipe::writeFrame(const std::uint8_t* rgba, std::size_t bytes) {
  if (!writeAll(rgba, bytes)) {
    const std::string why = stopAndExplain();
    throw Error("IO MOVIE", "ffmpeg stopped taking frames" + why);
  }
}

void FfmpegPipe::finish() {
  if (child_ <= 0) return;
  const std::string why = stopAndExplain();
  if (!why.empty()) throw Error("IO MOVIE", "ffmpeg failed" + why);
  if (std::rename(partial_.c_str(), path_.c_str()) != 0) {
    const std::string e = std::strerror(errno);
    std::remove(partial_.c_str());
    throw Error("IO MOVIE", "cannot rename the finished movie to " + path_ + ": " + e);
  }
}

// Writes without letting a dead ffmpeg's SIGPIPE end the process.
bool FfmpegPipe::writeAll(const std::uint8_t* data, std::size_t n) {
  if (pipe_ < 0) return false;
  sigset_t block, old;
  sigemptyset(&block);
  sigaddset(&block, SIGPIPE);
  pthread_sigmask(SIG_BLOCK, &block, &old);
  bool ok = true;
  while (n > 0) {
    const ssize_t w = ::write(pipe_, data, n);
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
std::string FfmpegPipe::stopAndExplain() {
  if (child_ <= 0) return "";
  if (pipe_ >= 0) ::close(pipe_);
  pipe_ = -1;
  int status = 0;
  while (::waitpid(child_, &status, 0) < 0 && errno == EINTR) {
  }
  child_ = -1;
  const bool ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  std::string why;
  if (!ok) {
    const std::string said = tail(log_, 400);
    why = said.empty() ? " (exit status " + std::to_string(WEXITSTATUS(status)) + ")" : ": " + said;
    std::remove(partial_.c_str());
  }
  std::remove(log_.c_str());
  return why;
}

void FfmpegPipe::stop() noexcept {
  if (child_ <= 0) return;
  try {
    stopAndExplain();
  } catch (...) {  // (a message that cannot be made: the files go all the same)
  }
  std::remove(partial_.c_str());
  std::remove(log_.c_str());
}

}  // namespace sf::io
