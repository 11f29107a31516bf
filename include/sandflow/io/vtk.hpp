#pragma once
// VTK XML output for ParaView: the lattice as ImageData (.vti) with the fields
// density, pressure, velocity and node kind at node centres.
#include <ostream>
#include <string>

#include "sandflow/dem/assembly.hpp"
#include "sandflow/lb/lattice.hpp"

namespace sf::io {

// The lattice as ImageData (.vti), binary appended data.
void writeLatticeVti(const lb::Lattice& lattice, std::ostream& out);

// Writes the elements as PolyData (.vtp): outlines (walls as lines) with cell
// data id, shape (0 disc, 1 polygon, 2 superquadric, 3 wall), velocity, spin, mass.
void writeElementsVtp(const dem::Assembly& assembly, std::ostream& out);

}  // namespace sf::io
