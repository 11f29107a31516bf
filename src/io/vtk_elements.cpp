// The elements as VTK XML PolyData (.vtp): each element's outline as a polygon
// (a wall as a line), with its id, shape type, velocity, spin and mass.
#include <cmath>
#include <numbers>
#include <sstream>

#include "sandflow/dem/polygon.hpp"
#include "sandflow/dem/superquadric.hpp"
#include "sandflow/io/vtk.hpp"

namespace sf::io {
namespace {

std::vector<Vec2> outline(const dem::Shape& s, const Vec2& x, double angle) {
  switch (s.type()) {
    case dem::ShapeType::disc: {
      const double r = static_cast<const dem::Disc&>(s).radius();
      std::vector<Vec2> p;
      for (int k = 0; k < 32; ++k) {
        const double t = angle + 2 * std::numbers::pi * k / 32;
        p.push_back(x + r * Vec2(std::cos(t), std::sin(t)));
      }
      return p;
    }
    case dem::ShapeType::polygon:
      return static_cast<const dem::Polygon&>(s).world(x, angle);
    case dem::ShapeType::superquadric:
      return static_cast<const dem::Superquadric&>(s).world(x, angle);
    case dem::ShapeType::wall: {
      const auto [a, b] = static_cast<const dem::Wall&>(s).ends(x, angle);
      return {a, b};
    }
  }
  return {};
}

}  // namespace

void writeElementsVtp(const dem::Assembly& assembly, std::ostream& out) {
  const dem::Bodies& b = assembly.bodies();
  std::ostringstream points, connectivity, offsets, lineConn, lineOff, ids, kinds, vel, spin, mass;
  points.precision(17);
  vel.precision(17);
  spin.precision(17);
  mass.precision(17);
  std::size_t nPoints = 0, polyEnd = 0, lineEnd = 0, nPolys = 0, nLines = 0;
  // VTK orders cell data as verts, lines, polys: write walls (lines) first.
  for (int pass = 0; pass < 2; ++pass)
    for (int s = 0; s < b.size(); ++s) {
      const bool wall = b.shape[s]->type() == dem::ShapeType::wall;
      if (wall != (pass == 0)) continue;
      const std::vector<Vec2> p = outline(*b.shape[s], b.x[s], b.angle[s]);
      for (std::size_t k = 0; k < p.size(); ++k) {
        points << p[k].x() << ' ' << p[k].y() << " 0\n";
        (wall ? lineConn : connectivity) << nPoints + k << ' ';
      }
      nPoints += p.size();
      if (wall)
        lineOff << (lineEnd += p.size()) << ' ', ++nLines;
      else
        offsets << (polyEnd += p.size()) << ' ', ++nPolys;
      ids << b.id[s] << ' ';
      kinds << int(b.shape[s]->type()) << ' ';
      vel << b.v[s].x() << ' ' << b.v[s].y() << " 0 ";
      spin << b.w[s] << ' ';
      mass << b.mass[s] << ' ';
    }
  std::ostringstream xml;
  xml << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" "
         "byte_order=\"LittleEndian\">\n  <PolyData>\n    <Piece NumberOfPoints=\""
      << nPoints << "\" NumberOfVerts=\"0\" NumberOfLines=\"" << nLines
      << "\" NumberOfStrips=\"0\" NumberOfPolys=\"" << nPolys << "\">\n"
      << "      <Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n"
      << points.str() << "      </DataArray></Points>\n"
      << "      <CellData Scalars=\"id\" Vectors=\"velocity\">\n"
      << "        <DataArray type=\"Int32\" Name=\"id\" format=\"ascii\">" << ids.str()
      << "</DataArray>\n"
      << "        <DataArray type=\"Int32\" Name=\"shape\" format=\"ascii\">" << kinds.str()
      << "</DataArray>\n"
      << "        <DataArray type=\"Float64\" Name=\"velocity\" NumberOfComponents=\"3\" "
         "format=\"ascii\">"
      << vel.str() << "</DataArray>\n"
      << "        <DataArray type=\"Float64\" Name=\"spin\" format=\"ascii\">" << spin.str()
      << "</DataArray>\n"
      << "        <DataArray type=\"Float64\" Name=\"mass\" format=\"ascii\">" << mass.str()
      << "</DataArray>\n      </CellData>\n"
      << "      <Lines>\n        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">"
      << lineConn.str() << "</DataArray>\n"
      << "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">" << lineOff.str()
      << "</DataArray>\n      </Lines>\n"
      << "      <Polys>\n        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">"
      << connectivity.str() << "</DataArray>\n"
      << "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">" << offsets.str()
      << "</DataArray>\n      </Polys>\n    </Piece>\n  </PolyData>\n</VTKFile>\n";
  out << xml.str();
}

}  // namespace sf::io
