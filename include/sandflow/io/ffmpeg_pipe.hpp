#pragma once
// A movie encoded by ffmpeg from raw RGBA frames written to its standard
// input. The movie is written under a temporary name beside it (".NAME.partEXT",
// ffmpeg's messages in ".NAME.ffmpeg.log") and appears whole, under its own
// name, when finished; a movie that fails or is abandoned leaves neither.
// Errors are sf::Error "IO MOVIE".
#include <sys/types.h>

#include <cstddef>
#include <cstdint>
#include <string>

namespace sf::io {

// Whether `path` ends in a container the movies are written as (.mp4, .mkv,
// .mov, .avi or .webm, in any case).
bool isMovieFile(const std::string& path);

class FfmpegPipe {
 public:
  // Starts `ffmpeg` (its path) on a movie of width x height frames at `fps`
  // frames per second. An unwritable folder fails here, at once.
  FfmpegPipe(const std::string& ffmpeg, std::string path, int width, int height, int fps);
  ~FfmpegPipe() { stop(); }
  FfmpegPipe(const FfmpegPipe&) = delete;
  FfmpegPipe& operator=(const FfmpegPipe&) = delete;

  // One frame: width x height x 4 bytes, top row first. When ffmpeg no longer
  // takes frames it is ended and the error says what it said last.
  void writeFrame(const std::uint8_t* rgba, std::size_t bytes);
  // Ends the input, waits for ffmpeg and renames the movie into place
  // (nothing when ffmpeg was already ended by a failure).
  void finish();

 private:
  bool writeAll(const std::uint8_t* data, std::size_t n);
  std::string stopAndExplain();
  void stop() noexcept;
  std::string path_, partial_, log_;
  pid_t child_ = -1;
  int pipe_ = -1;
};

}  // namespace sf::io
