#pragma once
// A recorder that writes a CSV time series (io::CsvWriter): one row per
// record with the step count, the time and the values of a subclass.
#include <string>
#include <vector>

#include "sandflow/io/csv_writer.hpp"
#include "sandflow/tcl/recorder.hpp"

namespace sf::tcl {

class CsvRecorder : public Recorder {
 public:
  // `columns` are the names after "step,time".
  CsvRecorder(std::string path, int every, const std::vector<std::string>& columns);
  // The first record creates (or truncates) the file and writes the header;
  // when it fails, no file is left.
  // While a checkpoint's recordings start again (Session::resumeStep), the
  // first record continues an existing file of the same columns: rows from
  // that step on are dropped, the header is kept.
  void record(const Session& s) final;
  void finish() final { writer_.close(); }
  bool resumable() const final { return true; }

 protected:
  // Appends this record's values, one per column; throws sf::Error when the
  // scene no longer has what a column needs.
  virtual void values(const Session& s, std::vector<double>& out) const = 0;

 private:
  io::CsvWriter writer_;
  std::vector<double> scratch_;
};

}  // namespace sf::tcl
