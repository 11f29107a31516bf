#pragma once
// VTK XML output for ParaView: the lattice as ImageData (.vti) with the fields
// density, pressure, velocity and node kind at node centres.
#include <string>

#include "sandflow/lb/lattice.hpp"

namespace sf::io {

// Writes `path` (normally ending in .vti). The file appears whole or not at all.
void writeLatticeVti(const lb::Lattice& lattice, const std::string& path);

}  // namespace sf::io
