#pragma once
// Finding an external program (gnuplot, ffmpeg) the way a shell would.
#include <string>

namespace sf::io {

// The full path of the executable regular file `name` in the first folder of
// $PATH that has one ("" for none). An empty entry is the current folder; an
// unset PATH is /usr/bin:/bin.
std::string findProgram(const std::string& name);

}  // namespace sf::io
