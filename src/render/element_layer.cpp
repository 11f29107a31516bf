// Elements, the markers of held ones, bonds, bond breaks and contact force chains.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "sandflow/dem/polygon.hpp"
#include "sandflow/dem/superquadric.hpp"
#include "scene_parts.hpp"

namespace sf::render::detail {
namespace {

constexpr Rgba kOutline{38, 38, 38, 255};
constexpr Rgba kWall{64, 64, 64, 255};
constexpr Rgba kBond{11, 61, 145, 255};
constexpr Rgba kBreak{214, 39, 40, 255};
constexpr Rgba kForce{178, 24, 43, 220};
constexpr Rgb kUnbonded{187, 187, 187};
constexpr Rgb kBonded{0, 114, 178};
constexpr Rgb kLostBond{213, 94, 0};
constexpr Rgba kMarker{255, 255, 255, 255};

std::vector<Vec2> worldOutline(const dem::Shape& shape, const Vec2& x, double angle,
                               const WorldMap& world) {
  switch (shape.type()) {
    case dem::ShapeType::disc: {
      const double r = static_cast<const dem::Disc&>(shape).radius();
      const int n = world.circleSides(r);
      std::vector<Vec2> pts(std::size_t(n), Vec2::Zero());
      for (int k = 0; k < n; ++k) {
        const double t = angle + 2 * std::numbers::pi * k / n;
        pts[std::size_t(k)] = x + r * Vec2(std::cos(t), std::sin(t));
      }
      return pts;
    }
    case dem::ShapeType::polygon:
      return static_cast<const dem::Polygon&>(shape).world(x, angle);
    case dem::ShapeType::superquadric:
      return static_cast<const dem::Superquadric&>(shape).world(x, angle);
    default:
      return {};
  }
}

// Per element: 0 no bond ever, 1 bonded, 2 has lost a bond.
std::vector<int> bondStates(const dem::Assembly& a) {
  std::vector<int> state(std::size_t(a.bodies().size()), 0);
  auto mark = [&](int id, int s) {
    const int slot = a.bodies().slot(id);
    if (slot >= 0) state[std::size_t(slot)] = std::max(state[std::size_t(slot)], s);
  };
  for (const dem::Bond& b : a.bonds()) {
    mark(b.idA, 1);
    mark(b.idB, 1);
  }
  for (const dem::BondBreak& b : a.breaks()) {
    mark(b.idA, 2);
    mark(b.idB, 2);
  }
  return state;
}

double valueOf(const dem::Bodies& b, int slot, ColorBy by) {
  return by == ColorBy::speed ? b.v[std::size_t(slot)].norm() : b.mass[std::size_t(slot)];
}

// A support's symbol at an element's centre (walls, held by default, have
// none): a triangle when it holds its position (x, y or both), a hatched
// base when it holds its rotation.
void addHoldMarker(Point c, std::uint8_t hold, float scale, DrawList& list) {
  const float u = 5 * scale;
  float base = c.y;
  if (hold & (dem::holdX | dem::holdY)) {
    base = c.y - 1.6f * u;
    std::vector<Point> triangle{{c.x, c.y}, {c.x - u, base}, {c.x + u, base}};
    addOutline(triangle, scale, kOutline, list.worldStrokes);
    list.fills.push_back({{c.x, c.y - u}, std::move(triangle), kMarker});
  }
  if (hold & dem::holdRotation) {
    list.worldStrokes.push_back(
        {{c.x - 1.4f * u, base}, {c.x + 1.4f * u, base}, 1.5f * scale, kOutline});
    for (int k = -1; k <= 1; ++k) {
      const float x = c.x + k * u;
      list.worldStrokes.push_back({{x, base}, {x - 0.6f * u, base - 0.6f * u}, scale, kOutline});
    }
  }
}

}  // namespace

ElementColouring elementColouring(const sim::Manager& m, const ViewOptions& v, Key* key) {
  ElementColouring c;
  c.by = v.colorBy;
  const dem::Bodies& b = m.assembly().bodies();
  if (v.colorBy == ColorBy::speed || v.colorBy == ColorBy::mass) {
    double lo = 0, hi = 0;
    bool any = false;
    for (int s = 0; s < b.size(); ++s) {
      if (b.shape[std::size_t(s)]->type() == dem::ShapeType::wall || b.ghost[std::size_t(s)])
        continue;
      const double x = valueOf(b, s, v.colorBy);
      lo = any ? std::min(lo, x) : x;
      hi = any ? std::max(hi, x) : x;
      any = true;
    }
    c.map = {ColorMap::viridis, v.colorBy == ColorBy::speed ? 0.0 : lo, hi};
    if (key) {
      key->title = v.colorBy == ColorBy::speed ? "element speed" : "element mass";
      key->continuous = true;
      key->map = c.map;
    }
  } else if (v.colorBy == ColorBy::bond && key) {
    key->title = "bonds";
    key->continuous = false;
    key->entries = {{"none", kUnbonded}, {"bonded", kBonded}, {"lost a bond", kLostBond}};
  }
  return c;
}

void addOutline(const std::vector<Point>& outline, float width, Rgba colour,
                std::vector<Stroke>& out) {
  for (std::size_t k = 0; k < outline.size(); ++k)
    out.push_back({outline[k], outline[(k + 1) % outline.size()], width, colour});
}

void addElements(const sim::Manager& m, const ViewOptions& v, const ElementColouring& colouring,
                 const WorldMap& world, float scale, DrawList& list) {
  const dem::Assembly& a = m.assembly();
  const dem::Bodies& b = a.bodies();
  const std::vector<int> bonds = v.colorBy == ColorBy::bond ? bondStates(a) : std::vector<int>();
  for (int s = 0; s < b.size(); ++s) {
    const std::size_t k = std::size_t(s);
    const dem::Shape& shape = *b.shape[k];
    if (shape.type() == dem::ShapeType::wall) {
      const auto& wall = static_cast<const dem::Wall&>(shape);
      const auto [p, q] = wall.ends(b.x[k], b.angle[k]);
      // A wall acts along its line (its thickness only sets its mass): drawn as a line.
      list.worldStrokes.push_back({world(p), world(q), 2.5f * scale, kWall});
      continue;
    }
    Rgb fill;
    switch (colouring.by) {
      case ColorBy::speed:
      case ColorBy::mass:
        fill = colouring.map(valueOf(b, s, colouring.by));
        break;
      case ColorBy::bond:
        fill = bonds[k] == 0 ? kUnbonded : bonds[k] == 1 ? kBonded : kLostBond;
        break;
      default: {
        const std::string& name = a.materials()[b.material[k]].name;
        const auto it = v.materialColors.find(name);
        fill = it != v.materialColors.end() ? it->second : paletteColor(b.material[k]);
      }
    }
    // A source's template touches nothing: drawn faint.
    const std::uint8_t alpha = b.ghost[k] ? 90 : 255;
    Fill f;
    f.centre = world(b.x[k]);
    f.colour = opaque(fill, alpha);
    for (const Vec2& p : worldOutline(shape, b.x[k], b.angle[k], world))
      f.outline.push_back(world(p));
    const Rgba line{kOutline.r, kOutline.g, kOutline.b, alpha};
    addOutline(f.outline, scale, line, list.worldStrokes);
    if (shape.type() == dem::ShapeType::disc)  // so that rotation shows
      list.worldStrokes.push_back({f.centre, f.outline.front(), scale, line});
    const Point centre = f.centre;
    if (v.fill) list.fills.push_back(std::move(f));
    if (b.hold[k]) addHoldMarker(centre, b.hold[k], scale, list);
  }
  if (v.bonds) {
    for (const dem::Bond& bond : a.bonds()) {
      const int sa = b.slot(bond.idA), sb = b.slot(bond.idB);
      if (sa < 0 || sb < 0) continue;
      list.worldStrokes.push_back(
          {world(b.x[std::size_t(sa)]), world(b.x[std::size_t(sb)]), 2 * scale, kBond});
    }
    // A broken bond is marked between its two elements where they are now
    // (where it broke may be far behind them).
    const float r = 3 * scale;
    for (const dem::BondBreak& br : a.breaks()) {
      const int sa = b.slot(br.idA), sb = b.slot(br.idB);
      if (sa < 0 || sb < 0) continue;
      const Point c = world(0.5 * (b.x[std::size_t(sa)] + b.x[std::size_t(sb)]));
      list.worldStrokes.push_back({{c.x - r, c.y - r}, {c.x + r, c.y + r}, 1.5f * scale, kBreak});
      list.worldStrokes.push_back({{c.x - r, c.y + r}, {c.x + r, c.y - r}, 1.5f * scale, kBreak});
    }
  }
  if (v.forces) {
    // Slots through the ids: after "element delete" the contact list keeps the
    // old slots until the next step's pair search.
    struct Chain {
      int a, b;
      const dem::Contact* c;
    };
    std::vector<Chain> chains;
    double fmax = 0;
    for (const dem::Contact& c : a.contacts()) {
      const int sa = b.slot(c.idA), sb = b.slot(c.idB);
      if (!c.touching || sa < 0 || sb < 0) continue;
      chains.push_back({sa, sb, &c});
      fmax = std::max(fmax, c.force.norm());
    }
    if (fmax > 0 && std::isfinite(fmax)) {
      // The strongest chain is as wide as two thirds of the smallest grain's radius.
      double smallest = 1e300;
      for (int s = 0; s < b.size(); ++s)
        if (b.shape[std::size_t(s)]->type() != dem::ShapeType::wall)
          smallest = std::min(smallest, b.shape[std::size_t(s)]->contactSize());
      const float widest =
          float(std::clamp(0.66 * world.length(smallest), 2.0 * scale, 200.0 * scale));
      for (const Chain& ch : chains) {
        const float w = std::max(1.0f * scale, float(ch.c->force.norm() / fmax) * widest);
        const bool wallA = b.shape[std::size_t(ch.a)]->type() == dem::ShapeType::wall;
        const bool wallB = b.shape[std::size_t(ch.b)]->type() == dem::ShapeType::wall;
        const Vec2 pa = wallA ? ch.c->point : b.x[std::size_t(ch.a)];
        const Vec2 pb = wallB ? ch.c->point : b.x[std::size_t(ch.b)];
        list.worldStrokes.push_back({world(pa), world(pb), w, kForce});
      }
    }
  }
}

}  // namespace sf::render::detail
