#pragma once
// The XML of an ASCII VTK PolyData file (.vtp), shared by the elements' and
// the bonds' writers. Values are written with 17 significant digits, so that
// a reader gets the doubles back exactly.
#include <cstddef>
#include <ostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "sandflow/geometry/vec2.hpp"

namespace sf::io::vtp {

// One array of cell data, or of field data (then `tuples` counts its values).
struct Array {
  Array(std::string name, std::string type, int components, std::string values,
        std::size_t tuples = 0)
      : name(std::move(name)),
        type(std::move(type)),
        components(components),
        values(std::move(values)),
        tuples(tuples) {}
  std::string name, type;  // type: a VTK XML type name (Int32, Float64, String)
  int components;
  std::string values;  // space-separated ASCII
  std::size_t tuples;
};

// Text for arrays of numbers: `add` appends one value, `add(Vec2)` a 3-vector
// with z = 0 (ParaView glyphs and plots 3-vectors).
class Values {
 public:
  Values() { text_.precision(17); }
  template <class T>
  void add(T value) {
    text_ << value << ' ';
  }
  void add(const Vec2& v) { text_ << v.x() << ' ' << v.y() << " 0 "; }
  std::string str() const { return text_.str(); }

 private:
  std::ostringstream text_;
};

// Cells of one kind (lines or polygons) over consecutive points.
struct Cells {
  std::string connectivity, offsets;
  std::size_t count = 0, end = 0;
  void add(std::size_t firstPoint, std::size_t points);
};

struct PolyData {
  Values points;  // x y 0 per point
  std::size_t nPoints = 0;
  Cells lines, polys;
  // VTK numbers cells verts, lines, strips, polys: cell data lists every line
  // before every polygon.
  std::vector<Array> cellData, fieldData;
  std::string scalars, vectors;  // the cell arrays ParaView shows first ("": none)
  void addPoint(const Vec2& p) {
    points.add(p);
    ++nPoints;
  }
};

void writePolyData(const PolyData& data, std::ostream& out);

// A String array's ASCII form: each string's bytes as numbers, each string
// ended by 0 (what VTK's own writer produces).
std::string stringValues(const std::vector<std::string>& strings);

}  // namespace sf::io::vtp
