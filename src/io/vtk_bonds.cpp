// The bonds as VTK XML PolyData (.vtp): one line per bond, between the centres
// of its two elements (as the view draws it), with its force and state.
#include "sandflow/io/vtk.hpp"
#include "vtk_polydata.hpp"

namespace sf::io {

void writeBondsVtp(const dem::Assembly& assembly, std::ostream& out) {
  const dem::Bodies& b = assembly.bodies();
  vtp::PolyData data;
  vtp::Values ids, elements, force, normal, shear, state;
  auto line = [&](int id, int idA, int idB, int a, int bb) {
    data.lines.add(data.nPoints, 2);
    data.addPoint(b.x[a]);
    data.addPoint(b.x[bb]);
    ids.add(id);
    elements.add(idA);
    elements.add(idB);
  };
  for (const dem::Bond& x : assembly.bonds()) {
    const int a = b.slot(x.idA), bb = b.slot(x.idB);
    if (a < 0 || bb < 0) continue;
    line(x.id, x.idA, x.idB, a, bb);
    // The bond's direction turns with the mean rotation of its elements
    // (BondSet::addForces); tension is a positive normal force.
    const Vec2 n = rotated(x.normal0, 0.5 * ((b.angle[a] - x.angleA0) + (b.angle[bb] - x.angleB0)));
    const double along = x.force.dot(n);
    force.add(x.force);
    normal.add(0.0 - along);  // (not -along: no "-0" for a bond at rest)
    shear.add((x.force - along * n).norm());
    state.add(0);
  }
  // A broken bond stays a line between its elements where they are now, with
  // no force (where it broke may be far behind them).
  for (const dem::BondBreak& x : assembly.breaks()) {
    const int a = b.slot(x.idA), bb = b.slot(x.idB);
    if (a < 0 || bb < 0) continue;
    line(x.bond, x.idA, x.idB, a, bb);
    force.add(Vec2(0, 0));
    normal.add(0.0);
    shear.add(0.0);
    state.add(x.tension ? 1 : 2);
  }
  data.cellData = {{"id", "Int32", 1, ids.str()},
                   {"elements", "Int32", 2, elements.str()},
                   {"force", "Float64", 3, force.str()},
                   {"normalforce", "Float64", 1, normal.str()},
                   {"shearforce", "Float64", 1, shear.str()},
                   {"state", "Int32", 1, state.str()}};
  data.scalars = "normalforce";
  data.vectors = "force";
  vtp::writePolyData(data, out);
}

}  // namespace sf::io
