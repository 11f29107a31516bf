#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

#include "sandflow/io/vtk.hpp"

namespace sf::io {
namespace {

// One appended-data array: raw little-endian bytes preceded by a UInt64 size.
struct Array {
  std::string name, type;
  int components;
  std::vector<char> bytes;
};

template <class T>
void append(std::vector<char>& out, T value) {
  const char* p = reinterpret_cast<const char*>(&value);
  out.insert(out.end(), p, p + sizeof(T));
}

}  // namespace

void writeLatticeVti(const lb::Lattice& lattice, std::ostream& out) {
  const int nx = lattice.nx(), ny = lattice.ny();
  const std::size_t n = lattice.nodes();
  Array density{"density", "Float64", 1, {}}, pressure{"pressure", "Float64", 1, {}},
      velocity{"velocity", "Float64", 3, {}}, kind{"kind", "UInt8", 1, {}},
      solid{"solid", "Float64", 1, {}};
  // The solid ratio moving solids gave each node in the last step.
  std::vector<double> eps(n, 0.0);
  for (const lb::CoveredCell& c : lattice.coveredCells()) {
    const int ci = int(c.node % (nx + 2)) - 1, cj = int(c.node / (nx + 2)) - 1;
    eps[std::size_t(cj) * nx + ci] = c.eps;
  }
  density.bytes.reserve(n * 8);
  pressure.bytes.reserve(n * 8);
  velocity.bytes.reserve(n * 24);
  kind.bytes.reserve(n);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      append(density.bytes, lattice.density(i, j));
      append(pressure.bytes, lattice.pressure(i, j));
      const Vec2 u = lattice.velocity(i, j);
      append(velocity.bytes, u.x());
      append(velocity.bytes, u.y());
      append(velocity.bytes, 0.0);
      append(kind.bytes, static_cast<std::uint8_t>(lattice.kind(i, j)));
      append(solid.bytes, eps[std::size_t(j) * nx + i]);
    }
  const Array* arrays[] = {&density, &pressure, &velocity, &kind, &solid};

  const auto& p = lattice.params();
  const Vec2 first = lattice.position(0, 0);
  std::ostringstream xml;
  xml.precision(17);
  xml << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"ImageData\" version=\"1.0\" byte_order=\"LittleEndian\" "
         "header_type=\"UInt64\">\n"
      << "  <ImageData WholeExtent=\"0 " << nx - 1 << " 0 " << ny - 1 << " 0 0\" Origin=\""
      << first.x() << " " << first.y() << " 0\" Spacing=\"" << p.h << " " << p.h << " " << p.h
      << "\">\n"
      << "    <Piece Extent=\"0 " << nx - 1 << " 0 " << ny - 1 << " 0 0\">\n"
      << "      <PointData Scalars=\"density\" Vectors=\"velocity\">\n";
  std::uint64_t offset = 0;
  for (const Array* a : arrays) {
    xml << "        <DataArray type=\"" << a->type << "\" Name=\"" << a->name
        << "\" NumberOfComponents=\"" << a->components << "\" format=\"appended\" offset=\""
        << offset << "\"/>\n";
    offset += sizeof(std::uint64_t) + a->bytes.size();
  }
  xml << "      </PointData>\n    </Piece>\n  </ImageData>\n"
      << "  <AppendedData encoding=\"raw\">\n   _";

  const std::string head = xml.str();
  out.write(head.data(), std::streamsize(head.size()));
  for (const Array* a : arrays) {
    const std::uint64_t size = a->bytes.size();
    out.write(reinterpret_cast<const char*>(&size), sizeof size);
    out.write(a->bytes.data(), std::streamsize(a->bytes.size()));
  }
  out << "\n  </AppendedData>\n</VTKFile>\n";
}

}  // namespace sf::io
