#include "sandflow/io/csv_table.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>

#include "sandflow/core/error.hpp"

namespace sf::io {
namespace {

std::vector<std::string> splitFields(const std::string& line) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(trim(line.substr(start, comma - start)));
    if (comma == std::string::npos) return fields;
    start = comma + 1;
  }
}

// The Tcl-style message for a column that is not in the header.
std::string badColumn(const std::string& name, const std::vector<std::string>& names,
                      const std::string& file) {
  std::string message =
      "bad column \"" + name + "\"" + (file.empty() ? "" : " in \"" + file + "\"") + ": must be ";
  for (std::size_t k = 0; k < names.size(); ++k) {
    if (k > 0) message += names.size() > 2 ? ", " : " ";
    if (k > 0 && k + 1 == names.size()) message += "or ";
    message += names[k];
  }
  return message;
}

}  // namespace

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

CsvTable readCsv(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("IO OPEN", "cannot read \"" + path + "\": " + std::strerror(errno));
  CsvTable csv;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (trim(line).empty()) continue;
    std::vector<std::string> fields = splitFields(line);
    if (csv.names.empty()) {
      csv.names = std::move(fields);
      continue;
    }
    if (fields.size() != csv.names.size())
      throw Error("VALUE CSV", "line " + std::to_string(number) + " of \"" + path + "\" has " +
                                   std::to_string(fields.size()) + " values, the header " +
                                   std::to_string(csv.names.size()) + " columns");
    csv.rows.push_back(std::move(fields));
    csv.lines.push_back(number);
  }
  if (in.bad()) throw Error("IO READ", "reading \"" + path + "\" failed");
  if (csv.names.empty()) throw Error("VALUE CSV", "\"" + path + "\" is empty: no header line");
  if (csv.rows.empty()) throw Error("VALUE CSV", "\"" + path + "\" has a header but no data rows");
  return csv;
}

int columnIndex(const CsvTable& csv, const std::string& name, const std::string& file,
                const std::string& main) {
  for (std::size_t k = 0; k < csv.names.size(); ++k)
    if (csv.names[k] == name) return int(k);
  throw Error("LOOKUP COLUMN", badColumn(name, csv.names, file != main ? file : ""));
}

}  // namespace sf::io
