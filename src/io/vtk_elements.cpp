// The elements as VTK XML PolyData (.vtp): each element's outline as a polygon
// (a wall as a line), with its state as cell data.
#include <cmath>
#include <numbers>

#include "sandflow/dem/polygon.hpp"
#include "sandflow/dem/superquadric.hpp"
#include "sandflow/io/vtk.hpp"
#include "vtk_polydata.hpp"

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
  vtp::PolyData data;
  vtp::Values ids, kinds, vel, spin, mass, angle, force, torque, material, fluidForce, fluidTorque;
  // Cell data lists lines before polygons: walls (lines) first.
  for (int pass = 0; pass < 2; ++pass)
    for (int s = 0; s < b.size(); ++s) {
      const bool wall = b.shape[s]->type() == dem::ShapeType::wall;
      if (wall != (pass == 0)) continue;
      const std::vector<Vec2> p = outline(*b.shape[s], b.x[s], b.angle[s]);
      (wall ? data.lines : data.polys).add(data.nPoints, p.size());
      for (const Vec2& q : p) data.addPoint(q);
      ids.add(b.id[s]);
      kinds.add(int(b.shape[s]->type()));
      vel.add(b.v[s]);
      spin.add(b.w[s]);
      mass.add(b.mass[s]);
      angle.add(b.angle[s]);
      force.add(b.force[s]);
      torque.add(b.torque[s]);
      material.add(b.material[s]);
      fluidForce.add(b.fluidForce[s]);
      fluidTorque.add(b.fluidTorque[s]);
    }
  data.cellData = {{"id", "Int32", 1, ids.str()},
                   {"shape", "Int32", 1, kinds.str()},
                   {"velocity", "Float64", 3, vel.str()},
                   {"spin", "Float64", 1, spin.str()},
                   {"mass", "Float64", 1, mass.str()},
                   {"angle", "Float64", 1, angle.str()},
                   {"force", "Float64", 3, force.str()},
                   {"torque", "Float64", 1, torque.str()},
                   {"material", "Int32", 1, material.str()},
                   {"fluidforce", "Float64", 3, fluidForce.str()},
                   {"fluidtorque", "Float64", 1, fluidTorque.str()}};
  // The material numbers name materials through this table (ParaView shows
  // field data in its spreadsheet view).
  const std::vector<std::string> names = assembly.materials().names();
  data.fieldData = {{"materialnames", "String", 1, vtp::stringValues(names), names.size()}};
  data.scalars = "id";
  data.vectors = "velocity";
  vtp::writePolyData(data, out);
}

}  // namespace sf::io
