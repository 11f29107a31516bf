#include "shape_state.hpp"

#include <cmath>

#include "sandflow/dem/polygon.hpp"
#include "sandflow/dem/superquadric.hpp"
#include "sandflow/geometry/vec2_bytes.hpp"

namespace sf::dem {

void saveShape(ByteWriter& out, const Shape& shape) {
  out.put(std::uint8_t(shape.type()));
  switch (shape.type()) {
    case ShapeType::disc:
      out.put(static_cast<const Disc&>(shape).radius());
      break;
    case ShapeType::wall: {
      const auto& w = static_cast<const Wall&>(shape);
      out.put(w.length()), out.put(w.thickness());
      break;
    }
    case ShapeType::superquadric: {
      const auto& q = static_cast<const Superquadric&>(shape);
      out.put(q.a()), out.put(q.b()), out.put(q.m()), out.put(q.n());
      out.put(std::int32_t(q.samples()));
      break;
    }
    case ShapeType::polygon: {
      const auto& p = static_cast<const Polygon&>(shape);
      putVec2s(out, p.vertices());
      out.put(p.area());
      break;
    }
  }
}

std::unique_ptr<Shape> loadShape(ByteReader& in) {
  const auto type = in.get<std::uint8_t>("shape");
  auto positive = [](double v) { return std::isfinite(v) && v > 0; };
  switch (ShapeType(type)) {
    case ShapeType::disc: {
      const double r = in.get<double>("disc");
      if (!positive(r)) ByteReader::fail("it holds a disc of radius " + formatNumber(r));
      return std::make_unique<Disc>(r);
    }
    case ShapeType::wall: {
      const double length = in.get<double>("wall"), thickness = in.get<double>("wall");
      if (!positive(length) || !positive(thickness))
        ByteReader::fail("it holds a wall of length " + formatNumber(length));
      return std::make_unique<Wall>(length, thickness);
    }
    case ShapeType::superquadric: {
      const double a = in.get<double>("superquadric"), b = in.get<double>("superquadric");
      const double m = in.get<double>("superquadric"), n = in.get<double>("superquadric");
      return std::make_unique<Superquadric>(a, b, m, n, in.get<std::int32_t>("superquadric"));
    }
    case ShapeType::polygon: {
      std::vector<Vec2> vertices;
      getVec2s(in, vertices, "polygon");
      const double area = in.get<double>("polygon");
      Vec2 centroid;
      const Polygon check = Polygon::fromVertices(vertices, centroid);  // a convex outline?
      if (!(std::abs(check.area() - area) <= 1e-9 * area) ||
          !(centroid.norm() <= 1e-9 * check.boundingRadius()))
        ByteReader::fail("it holds a polygon whose area or centroid does not match its vertices");
      return std::make_unique<Polygon>(Polygon::fromCentred(std::move(vertices), area));
    }
  }
  ByteReader::fail("it holds an unknown shape type " + std::to_string(type));
}

}  // namespace sf::dem
