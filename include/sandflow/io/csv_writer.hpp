#pragma once
// Writing a CSV time series (output csv, record): a header "step,time,..."
// then one row per write, each number in full (round-trip) precision. Each
// row is flushed as it is written, so that a reader (plot) sees every row so
// far. Errors are sf::Error ("IO OPEN", "IO WRITE"); their messages leave the
// path to the caller.
#include <cstdio>
#include <string>
#include <vector>

namespace sf::io {

class CsvWriter {
 public:
  // `columns` are the names after "step,time".
  CsvWriter(std::string path, const std::vector<std::string>& columns);
  ~CsvWriter();
  CsvWriter(const CsvWriter&) = delete;
  CsvWriter& operator=(const CsvWriter&) = delete;

  // Writes one row of `values` (one per column). The first write creates (or
  // truncates) the file and writes the header; when it fails, no file is
  // left. When resumeStep >= 0, the first write instead continues an existing
  // file with the same header: its rows from resumeStep on are dropped (a run
  // that went on past a checkpoint wrote them), the header is kept.
  void write(long long step, double time, const std::vector<double>& values,
             long long resumeStep = -1);
  // Flushes and closes the file (nothing when none is open).
  void close();
  bool isOpen() const { return file_ != nullptr; }

 private:
  void writeOrThrow(const std::string& text);
  bool resume(long long step);  // false: no such file (or another series) to continue
  std::string path_, header_;
  std::FILE* file_ = nullptr;
};

}  // namespace sf::io
