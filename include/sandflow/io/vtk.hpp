#pragma once
// VTK XML output for ParaView: the lattice as ImageData (.vti) with the fields
// density, pressure, velocity and node kind at node centres.
#include <string>

#include "sandflow/dem/assembly.hpp"
#include "sandflow/lb/lattice.hpp"

namespace sf::io {

// Writes `path` (normally ending in .vti). The file appears whole or not at all.
void writeLatticeVti(const lb::Lattice& lattice, const std::string& path);

// Writes the elements as PolyData (.vtp): outlines (walls as lines) with cell
// data id, shape (0 disc, 1 polygon, 2 superquadric, 3 wall), velocity, spin, mass.
void writeElementsVtp(const dem::Assembly& assembly, const std::string& path);

}  // namespace sf::io
