#pragma once
// The base of the outputs written while runs go on. It needs no Tcl: the
// files themselves are io's (CsvWriter, FfmpegPipe); the session
// (session.hpp) keeps the recorders and calls them.
#include <string>
#include <utility>

namespace sf::tcl {

struct Session;

// Output written while runs go on (output csv, movie, vtk -every; record):
// after every step whose count is a multiple of every(), record() is called;
// finish() completes the file. Both throw sf::Error on failure.
class Recorder {
 public:
  Recorder(std::string path, int every)
      : path_(std::move(path)), same_(samePath(path_)), every_(every) {}
  virtual ~Recorder() = default;
  virtual void record(const Session& s) = 0;
  virtual void finish() = 0;
  // Gives up before the first record was taken: removes what was started.
  // Must not throw.
  virtual void abandon() noexcept {
    try {
      finish();
    } catch (...) {
    }
  }
  virtual const char* kind() const = 0;  // "csv", "record", "movie", "vtk"
  // The command that started it (a Tcl list), which a checkpoint keeps; and
  // whether that command, run again as `checkpoint load` does, continues the
  // same file (CSV series: yes; a movie cannot be reopened).
  const std::string& command() const { return command_; }
  void setCommand(std::string command) { command_ = std::move(command); }
  virtual bool resumable() const { return false; }
  const std::string& path() const { return path_; }
  // The path in a form where "a.csv", "./a.csv" and "/abs/a.csv" agree.
  static std::string samePath(const std::string& path);
  bool writes(const std::string& path) const { return same_ == samePath(path); }
  int every() const { return every_; }
  long long written() const { return written_; }

 protected:
  long long written_ = 0;  // records (rows, frames) so far

 private:
  std::string path_, same_, command_;
  int every_;
};

}  // namespace sf::tcl
