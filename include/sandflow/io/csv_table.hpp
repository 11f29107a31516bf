#pragma once
// Reading a CSV file (what output csv and record write) as text, for plot:
// the header's names and each data row, with the line it came from so that a
// message can point at it. Errors are sf::Error ("IO ...", "VALUE CSV",
// "LOOKUP COLUMN").
#include <string>
#include <vector>

namespace sf::io {

// s without leading and trailing blanks, tabs and carriage returns.
std::string trim(const std::string& s);

struct CsvTable {
  std::vector<std::string> names;              // the header
  std::vector<std::vector<std::string>> rows;  // each as many fields as names, trimmed
  std::vector<int> lines;                      // each row's line number in the file
};

// Blank lines are skipped; a row with another number of fields than the
// header, a file with no header or no rows, is an error naming the file.
CsvTable readCsv(const std::string& path);

// A column's index. An unknown name is an error that lists the columns and,
// when `file` is not the plot's CSVFILE `main`, names `file`.
int columnIndex(const CsvTable& csv, const std::string& name, const std::string& file = "",
                const std::string& main = "");

}  // namespace sf::io
