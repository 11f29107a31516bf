// The element options' rows and the tables the element commands take.
#include "element_options.hpp"

#include <cmath>
#include <limits>

#include "sandflow/dem/polygon.hpp"

namespace sf::tcl {
namespace {

using dem::ShapeType;
using Row = Option<ElementDraft>;

const char* const kHoldNames[] = {"x", "y", "rot", nullptr};  // bits of dem::Hold

// Rows over one optional field of the draft: {} where it is not set.
template <class T, class Make>
OptionValue maybe(const std::optional<T>& v, Make make) {
  return v ? make(*v) : emptyValue();
}
Row vec2Row(OptionInfo info, std::optional<Vec2> ElementDraft::*f) {
  info.kind = ValueKind::vec2;
  return Row{info, [f](const ElementDraft& s) { return maybe(s.*f, vecValue); },
             [f](ElementDraft& s, const OptionValue& v) { s.*f = v.vec; }};
}
Row vec3Row(OptionInfo info, std::optional<Eigen::Vector3d> ElementDraft::*f) {
  info.kind = ValueKind::vec3;
  return Row{info, [f](const ElementDraft& s) { return maybe(s.*f, vec3Value); },
             [f](ElementDraft& s, const OptionValue& v) { s.*f = v.vec3; }};
}
Row realRow(OptionInfo info, std::optional<double> ElementDraft::*f) {
  info.kind = ValueKind::real;
  return Row{info, [f](const ElementDraft& s) { return maybe(s.*f, realValue); },
             [f](ElementDraft& s, const OptionValue& v) { s.*f = v.real; }};
}
Row integerRow(OptionInfo info, std::optional<int> ElementDraft::*f) {
  info.kind = ValueKind::integer;
  return Row{info, [f](const ElementDraft& s) { return maybe(s.*f, integerValue); },
             [f](ElementDraft& s, const OptionValue& v) { s.*f = v.integer; }};
}

// A polygon's corners: at least three points, convexity the kernel's to judge.
bool parseVertices(Tcl_Interp* interp, Tcl_Obj* value, ElementDraft& s) {
  int n = 0;
  Tcl_Obj** items = nullptr;
  if (Tcl_ListObjGetElements(interp, value, &n, &items) != TCL_OK) return false;
  if (n < 6 || n % 2)
    return reject(interp, "VALUE VERTICES",
                  "-vertices must be a list of at least 3 points {x1 y1 x2 y2 x3 y3 ...}");
  std::vector<Vec2> points;
  for (int i = 0; i < n; i += 2) {
    double x = 0, y = 0;
    if (!getDouble(interp, items[i], "-vertices", x) ||
        !getDouble(interp, items[i + 1], "-vertices", y))
      return false;
    points.emplace_back(x, y);
  }
  s.vertices = points;
  return true;
}

const Row kCenter = vec2Row(
    {.name = "-center", .synopsis = "{x y}", .help = "position of the centroid", .unit = "length"},
    &ElementDraft::center);
const Row kRadius = realRow({.name = "-radius",
                             .synopsis = "r",
                             .help = "disc radius",
                             .unit = "length",
                             .range = {.min = 0, .minOpen = true}},
                            &ElementDraft::radius);
const Row kFrom =
    vec2Row({.name = "-from", .synopsis = "{x y}", .help = "wall start point", .unit = "length"},
            &ElementDraft::from);
const Row kTo =
    vec2Row({.name = "-to", .synopsis = "{x y}", .help = "wall end point", .unit = "length"},
            &ElementDraft::to);
const Row kThickness = realRow({.name = "-thickness",
                                .synopsis = "t",
                                .help = "a wall's thickness, for its mass when set free",
                                .unit = "length",
                                .range = {.min = 0, .minOpen = true},
                                .defaultText = "1/20 of its length"},
                               &ElementDraft::thickness);
const Row kLength = realRow({.name = "-length",
                             .synopsis = "L",
                             .help = "a wall's length, with -center and -angle instead of -from "
                                     "and -to (its own pose, as element info reports it)",
                             .unit = "length",
                             .range = {.min = 0, .minOpen = true},
                             .defaultText = ""},
                            &ElementDraft::length);
// A choice among the session's materials: converted and shown by name.
const Row kMaterial{
    {.name = "-material",
     .synopsis = "NAME",
     .help = "the element's material, by name",
     .kind = ValueKind::choice,
     .defaultText = "default"},
    nullptr,
    nullptr,
    [](Tcl_Interp* interp, Tcl_Obj* v, ElementDraft& s) {
      const int m = s.materials ? s.materials->find(Tcl_GetString(v)) : -1;
      if (m < 0)
        return reject(interp, "LOOKUP MATERIAL",
                      std::string("no material named \"") + Tcl_GetString(v) + "\"");
      s.material = m;
      return true;
    },
    [](const ElementDraft& s) {
      return s.material && s.materials ? newString((*s.materials)[*s.material].name) : Tcl_NewObj();
    }};
const Row kAngle =
    realRow({.name = "-angle", .synopsis = "rad", .help = "orientation", .unit = "rad"},
            &ElementDraft::angle);
const Row kVelocity = vec3Row({.name = "-velocity",
                               .synopsis = "{vx vy w}",
                               .help = "velocity and angular velocity (prescribed where held)",
                               .unit = "length/time, rad/time"},
                              &ElementDraft::velocity);
const Row kFix{
    .info = {.name = "-fix",
             .synopsis = "{x y rot}",
             .help = "degrees of freedom held at their prescribed velocity; {} frees all",
             .kind = ValueKind::flags,
             .choices = kHoldNames,
             .what = "degree of freedom"},
    .get = [](const ElementDraft& s) { return maybe(s.hold, flagsValue); },
    .set = [](ElementDraft& s, const OptionValue& v) { s.hold = std::uint8_t(v.flags); }};
const Row kForce = vec3Row({.name = "-force",
                            .synopsis = "{Fx Fy T}",
                            .help = "applied force and torque",
                            .unit = "force, force length"},
                           &ElementDraft::force);
const Row kAcceleration = vec2Row({.name = "-acceleration",
                                   .synopsis = "{ax ay}",
                                   .help = "a body acceleration of its own, added to gravity",
                                   .unit = "length/time^2"},
                                  &ElementDraft::acceleration);
const Row kId = integerRow({.name = "-id",
                            .synopsis = "N",
                            .help = "the element's id",
                            .range = {.min = 0},
                            .defaultText = "the next free one"},
                           &ElementDraft::id);
const Row kVertices{.info = {.name = "-vertices",
                             .synopsis = "{x1 y1 x2 y2 ...}",
                             .help = "corners of a convex polygon, in either order",
                             .kind = ValueKind::custom,
                             .unit = "length"},
                    .parse = parseVertices,
                    .show = [](const ElementDraft&) { return Tcl_NewObj(); }};
// Semi-axes and exponents: their ranges are the kernel's (dem/shape_checks.hpp),
// checked whole before a shape is made.
const Row kAxes = vec2Row({.name = "-axes",
                           .synopsis = "{a b}",
                           .help = "semi-axes of the ellipse along its own x and y",
                           .unit = "length"},
                          &ElementDraft::axes);
const Row kSides = integerRow({.name = "-sides",
                               .synopsis = "N",
                               .help = "sides of the polygon that approximates the ellipse",
                               .range = {.min = 3, .max = 10000}},
                              &ElementDraft::sides);
// A superquadric's outline samples: the kernel takes no fewer than 8.
const Row kSamples =
    integerRow({.name = "-sides",
                .synopsis = "N",
                .help = "points that sample the superquadric's outline for contacts",
                .range = {.min = 8, .max = 10000},
                .outOfRange =
                    [](double n) {
                      return "-sides must be 8 to 10000 for a superquadric, got " + formatNumber(n);
                    }},
               &ElementDraft::sides);
const Row kStress{
    .info = {.name = "-stress",
             .synopsis = "s",
             .help = "a wall becomes a plate holding stress s (load s x length) on what it "
                     "presses; {} stops",
             .unit = "force/length",
             .orEmpty = true},
    .get = [](const ElementDraft& s) { return maybe(s.stress, realValue); },
    .set =
        [](ElementDraft& s, const OptionValue& v) {
          s.stress = v.empty ? std::numeric_limits<double>::quiet_NaN() : v.real;
        }};
const Row kExponents = vec2Row({.name = "-exponents",
                                .synopsis = "{m n}",
                                .help = "superquadric exponents, 1 to 100: |x/a|^m + |y/b|^n = 1"},
                               &ElementDraft::exponents);

}  // namespace

ElementDraft ElementDraft::of(const dem::Assembly& a, int slot) {
  const dem::Bodies& b = a.bodies();
  const dem::Shape& shape = *b.shape[slot];
  ElementDraft s;
  s.materials = &a.materials();
  s.center = b.x[slot];
  if (shape.type() == ShapeType::disc) s.radius = static_cast<const dem::Disc&>(shape).radius();
  if (shape.type() == ShapeType::wall) {
    const auto [p, q] = static_cast<const dem::Wall&>(shape).ends(b.x[slot], b.angle[slot]);
    s.from = p, s.to = q;
    s.thickness = static_cast<const dem::Wall&>(shape).thickness();
  }
  s.material = b.material[slot];
  s.angle = b.angle[slot];
  s.velocity = Eigen::Vector3d(b.v[slot].x(), b.v[slot].y(), b.w[slot]);
  s.hold = b.hold[slot];
  s.force =
      Eigen::Vector3d(b.appliedForce[slot].x(), b.appliedForce[slot].y(), b.appliedTorque[slot]);
  s.acceleration = b.acceleration[slot];
  s.stress = b.stress[slot];
  s.id = b.id[slot];
  return s;
}

ElementDraft ElementDraft::defaults(ShapeType shape) {
  ElementDraft s;
  s.angle = 0;
  s.velocity = s.force = Eigen::Vector3d::Zero();
  s.hold = shape == ShapeType::wall ? dem::holdX | dem::holdY | dem::holdRotation : 0;
  s.acceleration = Vec2::Zero();
  s.sides = 32;
  s.stress = std::numeric_limits<double>::quiet_NaN();
  return s;
}

const ElementTable& discOptions() {
  static const ElementTable t{kCenter, kRadius, kMaterial,     kAngle, kVelocity,
                              kFix,    kForce,  kAcceleration, kId};
  return t;
}
const ElementTable& wallOptions() {
  static const ElementTable t{kFrom,         kTo,    kCenter,   kLength, kThickness,
                              kMaterial,     kAngle, kVelocity, kFix,    kForce,
                              kAcceleration, kId,    kStress};
  return t;
}
const ElementTable& polygonOptions() {
  static const ElementTable t{kVertices, kMaterial, kAngle,        kVelocity,
                              kFix,      kForce,    kAcceleration, kId};
  return t;
}
const ElementTable& ellipseOptions() {
  static const ElementTable t{kCenter,   kAxes, kSides, kMaterial,     kAngle,
                              kVelocity, kFix,  kForce, kAcceleration, kId};
  return t;
}
const ElementTable& superquadricOptions() {
  static const ElementTable t{kCenter,   kAxes, kExponents, kSamples,      kMaterial, kAngle,
                              kVelocity, kFix,  kForce,     kAcceleration, kId};
  return t;
}
const ElementTable& configureOptions() {
  static const ElementTable t{kCenter,   kRadius, kFrom,  kTo,           kMaterial, kAngle,
                              kVelocity, kFix,    kForce, kAcceleration, kStress};
  return t;
}

// Whether configure's option applies to a shape, as the kernel has it
// (dem::partsOf).
static bool appliesTo(const std::string& option, ShapeType shape) {
  const dem::ShapeParts parts = dem::partsOf(shape);
  if (option == "-radius") return parts.radius;
  if (option == "-from" || option == "-to") return parts.ends;
  if (option == "-stress") return parts.stress;
  return true;
}

Tcl_Obj* describeConfigureOptions(const dem::MaterialTable& materials,
                                  std::optional<ShapeType> shape) {
  const ElementTable& table = configureOptions();
  Tcl_Obj* all = table.describe(ElementDraft::defaults(shape.value_or(ShapeType::disc)));
  Tcl_Obj* names = Tcl_NewListObj(0, nullptr);
  for (const std::string& n : materials.names())
    Tcl_ListObjAppendElement(nullptr, names, newString(n));
  Tcl_Obj* key = Tcl_NewStringObj("choices", -1);
  Tcl_IncrRefCount(key);
  Tcl_IncrRefCount(all);
  int n = 0;
  Tcl_Obj** items = nullptr;
  Tcl_ListObjGetElements(nullptr, all, &n, &items);
  Tcl_Obj* rows = Tcl_NewListObj(0, nullptr);
  for (int k = 0; k < n; ++k) {
    const std::string name = table.info(k).name;
    if (shape && !appliesTo(name, *shape)) continue;
    if (name == "-material") Tcl_DictObjPut(nullptr, items[k], key, names);
    Tcl_ListObjAppendElement(nullptr, rows, items[k]);
  }
  Tcl_DecrRefCount(all);
  Tcl_DecrRefCount(key);
  return rows;
}

}  // namespace sf::tcl
