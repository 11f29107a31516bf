#include "sandflow/io/csv_writer.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

#include "sandflow/core/error.hpp"

namespace sf::io {

CsvWriter::CsvWriter(std::string path, const std::vector<std::string>& columns)
    : path_(std::move(path)), header_("step,time") {
  for (const std::string& c : columns) {
    header_ += ',';
    header_ += c;
  }
  header_ += '\n';
}

CsvWriter::~CsvWriter() {
  if (file_) std::fclose(file_);
}

void CsvWriter::writeOrThrow(const std::string& text) {
  // One row at a time, flushed: a row is in the file, whole, once write() returns.
  if (std::fwrite(text.data(), 1, text.size(), file_) != text.size() || std::fflush(file_) != 0)
    throw Error("IO WRITE", std::string("writing failed: ") + std::strerror(errno));
}

void CsvWriter::write(long long step, double time, const std::vector<double>& values,
                      long long resumeStep) {
  std::string row = std::to_string(step) + "," + formatNumber(time);
  for (double v : values) {
    row += ',';  // (appending pieces: "," + s trips a false -Wrestrict of GCC 12)
    row += formatNumber(v);
  }
  row += "\n";
  const bool first = !file_;
  if (first && resumeStep >= 0 && resume(resumeStep)) {
    writeOrThrow(row);
    return;
  }
  if (first) {
    file_ = std::fopen(path_.c_str(), "we");  // close-on-exec: not for ffmpeg or gnuplot
    if (!file_)
      throw Error("IO OPEN", std::string("cannot open it for writing: ") + std::strerror(errno));
    row = header_ + row;
  }
  try {
    writeOrThrow(row);
  } catch (const Error&) {
    if (first) {  // no half-made file
      std::fclose(file_);
      file_ = nullptr;
      std::remove(path_.c_str());
    }
    throw;
  }
}

bool CsvWriter::resume(long long step) {
  std::FILE* f = std::fopen(path_.c_str(), "r+e");
  if (!f) return false;  // nothing to continue: a fresh file
  std::string text;
  char buffer[65536];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, f)) > 0;) text.append(buffer, n);
  if (std::ferror(f) || text.compare(0, header_.size(), header_) != 0) {
    std::fclose(f);  // another series, or unreadable: start afresh
    return false;
  }
  // Keep the rows before `step`; the row for `step` itself comes next.
  std::size_t keep = header_.size();
  while (keep < text.size()) {
    const std::size_t end = text.find('\n', keep);
    if (end == std::string::npos || std::atoll(text.c_str() + keep) >= step) break;
    keep = end + 1;
  }
  if (std::fflush(f) != 0 || ftruncate(fileno(f), off_t(keep)) != 0 ||
      std::fseek(f, 0, SEEK_END) != 0) {
    std::fclose(f);
    throw Error("IO WRITE", std::string("cannot continue it: ") + std::strerror(errno));
  }
  file_ = f;
  return true;
}

void CsvWriter::close() {
  if (!file_) return;
  const bool flushed = std::fflush(file_) == 0;
  const int error = errno;
  const bool closed = std::fclose(file_) == 0;
  file_ = nullptr;
  if (!flushed || !closed)
    throw Error("IO WRITE",
                std::string("closing failed: ") + std::strerror(flushed ? errno : error));
}

}  // namespace sf::io
