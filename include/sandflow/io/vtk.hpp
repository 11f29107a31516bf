#pragma once
// VTK XML output for ParaView: the lattice as ImageData (.vti), the elements
// and the bonds as PolyData (.vtp), and a collection (.pvd) that lists a
// series of them with their times.
#include <ostream>
#include <string>
#include <vector>

#include "sandflow/dem/assembly.hpp"
#include "sandflow/lb/lattice.hpp"

namespace sf::io {

// The lattice as ImageData (.vti), binary appended data: the fields density,
// pressure, velocity, node kind and solid ratio at node centres.
void writeLatticeVti(const lb::Lattice& lattice, std::ostream& out);

// Writes the elements as PolyData (.vtp): outlines (walls as lines) with cell
// data id, shape (0 disc, 1 polygon, 2 superquadric, 3 wall), velocity, spin,
// mass, angle, force, torque, material (an index into the field data
// materialnames), fluidforce and fluidtorque.
void writeElementsVtp(const dem::Assembly& assembly, std::ostream& out);

// Writes the bonds as PolyData (.vtp): a line between the centres of each
// bond's elements, with cell data id, elements, force (on the second element),
// normalforce (tension > 0), shearforce and state (0 intact, 1 broken in
// tension, 2 broken in shear; a broken bond has no force).
void writeBondsVtp(const dem::Assembly& assembly, std::ostream& out);

// One file of a collection: `part` numbers the data set within a time step
// (the same for the same kind of file at every time), `file` is relative to
// the collection's folder.
struct CollectionEntry {
  double time;
  int part;
  std::string name, file;
};

// A ParaView data collection (.pvd) listing `entries` in order.
void writeCollectionPvd(const std::vector<CollectionEntry>& entries, std::ostream& out);

}  // namespace sf::io
