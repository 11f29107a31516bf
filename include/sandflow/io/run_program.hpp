#pragma once
// Running an external program to completion (gnuplot): its input given, its
// output and error output captured together.
#include <string>
#include <vector>

namespace sf::io {

struct ProgramRun {
  bool ok = false;     // it ran and exited with status 0
  std::string output;  // what it wrote, then why it failed (as Tcl's exec says it)
};

// Runs args[0] (a path) with the arguments after it; `input` is its standard
// input. Does not throw for the program's failure, nor when it cannot start:
// `output` then says why.
ProgramRun runProgram(const std::vector<std::string>& args, const std::string& input);

}  // namespace sf::io
