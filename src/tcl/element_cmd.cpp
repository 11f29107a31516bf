// disc create, wall create, element configure|cget|info|ids|delete|next|help
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "sandflow/dem/polygon.hpp"
#include "sandflow/dem/shape_checks.hpp"
#include "sandflow/dem/superquadric.hpp"
#include "sandflow/tcl/args.hpp"
#include "sandflow/tcl/session.hpp"

namespace sf::tcl {
namespace {

using dem::ElementDef;
using dem::ShapeType;

enum Field {
  fCenter,
  fRadius,
  fFrom,
  fTo,
  fThickness,
  fMaterial,
  fAngle,
  fVelocity,
  fFix,
  fForce,
  fAcceleration,
  fId,
  fVertices,
  fAxes,
  fSides,
  fStress,
  fExponents
};

// Every option an element command may take; each command's table is a subset.
const OptionSpec kAll[] = {
    {"-center", "{x y}", "position of the centroid"},
    {"-radius", "r", "disc radius"},
    {"-from", "{x y}", "wall start point"},
    {"-to", "{x y}", "wall end point"},
    {"-thickness", "t",
     "a wall's thickness, for its mass when set free (default 1/20 of its length)"},
    {"-material", "NAME", "material (default \"default\")"},
    {"-angle", "rad", "orientation"},
    {"-velocity", "{vx vy w}", "velocity and angular velocity (prescribed where held)"},
    {"-fix", "{x y rot}", "degrees of freedom held at their prescribed velocity; {} frees all"},
    {"-force", "{Fx Fy T}", "applied force and torque"},
    {"-acceleration", "{ax ay}", "a body acceleration of its own, added to gravity"},
    {"-id", "N", "the element's id (default: the next free one)"},
    {"-vertices", "{x1 y1 x2 y2 ...}", "corners of a convex polygon, in either order"},
    {"-axes", "{a b}", "semi-axes of the ellipse along its own x and y"},
    {"-sides", "N", "sides of the polygon that approximates the ellipse (default 32)"},
    {"-stress", "s",
     "a wall becomes a plate holding stress s (load s x length) on what it presses; {} stops"},
    {"-exponents", "{m n}", "superquadric exponents, 1 to 100: |x/a|^m + |y/b|^n = 1"},
};

struct Table {
  std::vector<OptionSpec> specs;
  std::vector<Field> fields;
  explicit Table(std::initializer_list<Field> f) : fields(f) {
    for (Field x : fields) specs.push_back(kAll[x]);
    specs.push_back({nullptr, nullptr, nullptr});
  }
};

const Table& discTable() {
  static const Table t{fCenter, fRadius, fMaterial,     fAngle, fVelocity,
                       fFix,    fForce,  fAcceleration, fId};
  return t;
}
const Table& wallTable() {
  static const Table t{fFrom, fTo,    fThickness,    fMaterial, fAngle, fVelocity,
                       fFix,  fForce, fAcceleration, fId,       fStress};
  return t;
}
const Table& polygonTable() {
  static const Table t{fVertices, fMaterial, fAngle, fVelocity, fFix, fForce, fAcceleration, fId};
  return t;
}
const Table& ellipseTable() {
  static const Table t{fCenter,   fAxes, fSides, fMaterial,     fAngle,
                       fVelocity, fFix,  fForce, fAcceleration, fId};
  return t;
}
const Table& superquadricTable() {
  static const Table t{fCenter,   fAxes, fExponents, fSides,        fMaterial, fAngle,
                       fVelocity, fFix,  fForce,     fAcceleration, fId};
  return t;
}
const Table& configureTable() {
  static const Table t{fCenter,   fRadius, fFrom,  fTo,           fMaterial, fAngle,
                       fVelocity, fFix,    fForce, fAcceleration, fStress};
  return t;
}

// Option values, converted and range-checked, not yet applied.
struct Edit {
  std::optional<Vec2> center, from, to, acceleration;
  std::optional<double> radius, thickness, angle;
  std::optional<int> material, id;
  std::optional<Eigen::Vector3d> velocity, force;
  std::optional<std::uint8_t> hold;
  std::optional<std::vector<Vec2>> vertices;
  std::optional<Vec2> axes, exponents;
  std::optional<int> sides;
  std::optional<double> stress;  // NaN: remove the servo
};

bool getVec3(Tcl_Interp* interp, Tcl_Obj* obj, const char* what, Eigen::Vector3d& out) {
  std::vector<double> v;
  if (!getDoubles(interp, obj, what, 3, v)) return false;
  out = Eigen::Vector3d(v[0], v[1], v[2]);
  return true;
}

bool getHold(Tcl_Interp* interp, Tcl_Obj* obj, std::uint8_t& hold) {
  static const char* const names[] = {"x", "y", "rot", nullptr};
  int n = 0;
  Tcl_Obj** items = nullptr;
  if (Tcl_ListObjGetElements(interp, obj, &n, &items) != TCL_OK) return false;
  hold = 0;
  for (int i = 0; i < n; ++i) {
    int k = 0;
    if (!getChoice(interp, items[i], "degree of freedom", names, k)) {
      Tcl_AddErrorInfo(interp, "\n    (in -fix option)");
      return false;
    }
    hold |= std::uint8_t(1u << k);
  }
  return true;
}

bool parseEdit(Tcl_Interp* interp, int objc, Tcl_Obj* const objv[], int first, const Table& table,
               const dem::Assembly& assembly, Edit& e) {
  return parseOptions(interp, objc, objv, first, table.specs.data(), [&](int index, Tcl_Obj* v) {
    const Field f = table.fields[index];
    const char* name = kAll[f].name;
    double d = 0;
    Vec2 p;
    switch (f) {
      case fCenter:
      case fFrom:
      case fTo:
      case fAcceleration:
        if (!getVec2(interp, v, name, p)) return false;
        (f == fCenter ? e.center : f == fFrom ? e.from : f == fTo ? e.to : e.acceleration) = p;
        return true;
      case fRadius:
      case fThickness:
        if (!getDouble(interp, v, name, d)) return false;
        if (!(d > 0))
          return reject(interp, std::string("VALUE ") + (f == fRadius ? "RADIUS" : "THICKNESS"),
                        std::string(name) + " must be > 0, got " + formatNumber(d));
        (f == fRadius ? e.radius : e.thickness) = d;
        return true;
      case fAngle:
        if (!getDouble(interp, v, name, d)) return false;
        e.angle = d;
        return true;
      case fMaterial: {
        const int m = assembly.materials().find(Tcl_GetString(v));
        if (m < 0)
          return reject(interp, "LOOKUP MATERIAL",
                        std::string("no material named \"") + Tcl_GetString(v) + "\"");
        e.material = m;
        return true;
      }
      case fVelocity:
      case fForce: {
        Eigen::Vector3d x;
        if (!getVec3(interp, v, name, x)) return false;
        (f == fVelocity ? e.velocity : e.force) = x;
        return true;
      }
      case fFix: {
        std::uint8_t h = 0;
        if (!getHold(interp, v, h)) return false;
        e.hold = h;
        return true;
      }
      case fVertices: {
        int n = 0;
        Tcl_Obj** items = nullptr;
        if (Tcl_ListObjGetElements(interp, v, &n, &items) != TCL_OK) return false;
        if (n < 6 || n % 2)
          return reject(interp, "VALUE VERTICES",
                        "-vertices must be a list of at least 3 points {x1 y1 x2 y2 x3 y3 ...}");
        std::vector<Vec2> pts;
        for (int i = 0; i < n; i += 2) {
          double x = 0, y = 0;
          if (!getDouble(interp, items[i], name, x) || !getDouble(interp, items[i + 1], name, y))
            return false;
          pts.emplace_back(x, y);
        }
        e.vertices = pts;
        return true;
      }
      case fExponents:  // ranges: the kernel's (shapeOption)
      case fAxes:
        if (!getVec2(interp, v, name, p)) return false;
        (f == fAxes ? e.axes : e.exponents) = p;
        return true;
      case fSides: {
        int n = 0;
        if (!getInt(interp, v, name, n)) return false;
        if (n < 3 || n > 10000)
          return reject(interp, "VALUE SIDES",
                        "-sides must be 3 to 10000, got " + std::to_string(n));
        e.sides = n;
        return true;
      }
      case fStress:
        if (Tcl_GetCharLength(v) == 0) {
          e.stress = std::numeric_limits<double>::quiet_NaN();
          return true;
        }
        if (!getDouble(interp, v, name, d)) return false;
        e.stress = d;
        return true;
      case fId: {
        int id = 0;
        if (!getInt(interp, v, name, id)) return false;
        if (id < 0)
          return reject(interp, "VALUE ID", "-id must be >= 0, got " + std::to_string(id));
        e.id = id;
        return true;
      }
    }
    return true;
  });
}

// Settings shared by every shape, onto a definition.
void applyCommon(const Edit& e, ElementDef& def) {
  if (e.material) def.material = *e.material;
  if (e.angle) def.angle = *e.angle;
  if (e.velocity) def.v = e.velocity->head<2>(), def.w = (*e.velocity)[2];
  if (e.hold) def.hold = *e.hold;
  if (e.force) def.force = e.force->head<2>(), def.torque = (*e.force)[2];
  if (e.acceleration) def.acceleration = *e.acceleration;
  if (e.id) def.id = *e.id;
}

// A kernel check of one option's value (dem/shape_checks.hpp), before any
// shape is made: its sf::Error becomes the Tcl error, noted "(in OPTION option)".
template <class Check>
bool shapeOption(Tcl_Interp* interp, const char* option, Check&& check) {
  try {
    check();
    return true;
  } catch (const Error& error) {
    fail(interp, error);
    noteOptionOnce(interp, option);
    return false;
  }
}

int create(Tcl_Interp* interp, Session& s, ElementDef def) {
  return guarded(interp, [&] {
    Tcl_SetObjResult(interp, Tcl_NewIntObj(s.manager.assembly().add(std::move(def))));
    return TCL_OK;
  });
}

int DiscCreate(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  Session& s = sessionOf(data);
  if (objc % 2 == 0) {
    Tcl_WrongNumArgs(interp, 1, objv, "-center {x y} -radius r ?-option value ...?");
    return TCL_ERROR;
  }
  Edit e;
  if (!parseEdit(interp, objc, objv, 1, discTable(), s.manager.assembly(), e)) return TCL_ERROR;
  if (!e.center) return fail(interp, "VALUE CENTER", "disc create needs -center {x y}");
  if (!e.radius) return fail(interp, "VALUE RADIUS", "disc create needs -radius r");
  ElementDef def;
  def.shape = std::make_unique<dem::Disc>(*e.radius);
  def.x = *e.center;
  applyCommon(e, def);
  return create(interp, s, std::move(def));
}

int WallCreate(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  Session& s = sessionOf(data);
  if (objc % 2 == 0) {
    Tcl_WrongNumArgs(interp, 1, objv, "-from {x y} -to {x y} ?-option value ...?");
    return TCL_ERROR;
  }
  Edit e;
  if (!parseEdit(interp, objc, objv, 1, wallTable(), s.manager.assembly(), e)) return TCL_ERROR;
  if (!e.from || !e.to)
    return fail(interp, "VALUE WALL", "wall create needs -from {x y} and -to {x y}");
  const Vec2 seg = *e.to - *e.from;
  if (!(seg.norm() > 0))
    return fail(interp, "VALUE WALL", "wall has zero length: -from equals -to");
  if (e.angle) return fail(interp, "VALUE ANGLE", "a wall's angle follows from -from and -to");
  ElementDef def;
  def.shape = std::make_unique<dem::Wall>(seg.norm(), e.thickness.value_or(seg.norm() / 20));
  def.x = 0.5 * (*e.from + *e.to);
  def.angle = std::atan2(seg.y(), seg.x());
  def.hold = dem::holdX | dem::holdY | dem::holdRotation;  // walls stand still unless freed
  applyCommon(e, def);
  return guarded(interp, [&] {
    dem::Assembly& a = s.manager.assembly();
    const int id = a.add(std::move(def));
    if (e.stress) a.setPlateStress(id, *e.stress);
    Tcl_SetObjResult(interp, Tcl_NewIntObj(id));
    return TCL_OK;
  });
}

int PolygonCreate(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  Session& s = sessionOf(data);
  if (objc % 2 == 0) {
    Tcl_WrongNumArgs(interp, 1, objv, "-vertices {x1 y1 x2 y2 ...} ?-option value ...?");
    return TCL_ERROR;
  }
  Edit e;
  if (!parseEdit(interp, objc, objv, 1, polygonTable(), s.manager.assembly(), e)) return TCL_ERROR;
  if (!e.vertices) return fail(interp, "VALUE VERTICES", "polygon create needs -vertices");
  std::optional<dem::Polygon> polygon;
  Vec2 centroid;
  if (!shapeOption(interp, "-vertices",
                   [&] { polygon = dem::Polygon::fromVertices(*e.vertices, centroid); }))
    return TCL_ERROR;
  return guarded(interp, [&] {
    ElementDef def;
    def.shape = std::make_unique<dem::Polygon>(std::move(*polygon));
    def.x = centroid;
    applyCommon(e, def);
    return create(interp, s, std::move(def));
  });
}

int EllipseCreate(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  Session& s = sessionOf(data);
  if (objc % 2 == 0) {
    Tcl_WrongNumArgs(interp, 1, objv, "-center {x y} -axes {a b} ?-sides N? ?-option value ...?");
    return TCL_ERROR;
  }
  Edit e;
  if (!parseEdit(interp, objc, objv, 1, ellipseTable(), s.manager.assembly(), e)) return TCL_ERROR;
  if (!e.center) return fail(interp, "VALUE CENTER", "ellipse create needs -center {x y}");
  if (!e.axes) return fail(interp, "VALUE AXES", "ellipse create needs -axes {a b}");
  if (!shapeOption(interp, "-axes",
                   [&] { dem::checkSemiAxes(e.axes->x(), e.axes->y(), "ellipse"); }))
    return TCL_ERROR;
  const int n = e.sides.value_or(32);
  std::vector<Vec2> outline;
  for (int k = 0; k < n; ++k) {
    const double t = 2 * std::numbers::pi * k / n;
    outline.emplace_back(e.axes->x() * std::cos(t), e.axes->y() * std::sin(t));
  }
  return guarded(interp, [&] {
    ElementDef def;
    Vec2 centroid;
    def.shape = std::make_unique<dem::Polygon>(dem::Polygon::fromVertices(outline, centroid));
    def.x = *e.center;
    applyCommon(e, def);
    return create(interp, s, std::move(def));
  });
}

int SuperquadricCreate(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  Session& s = sessionOf(data);
  if (objc % 2 == 0) {
    Tcl_WrongNumArgs(interp, 1, objv,
                     "-center {x y} -axes {a b} -exponents {m n} ?-sides N? ?-option value ...?");
    return TCL_ERROR;
  }
  Edit e;
  if (!parseEdit(interp, objc, objv, 1, superquadricTable(), s.manager.assembly(), e))
    return TCL_ERROR;
  if (!e.center) return fail(interp, "VALUE CENTER", "superquadric create needs -center {x y}");
  if (!e.axes) return fail(interp, "VALUE AXES", "superquadric create needs -axes {a b}");
  if (!e.exponents)
    return fail(interp, "VALUE EXPONENTS", "superquadric create needs -exponents {m n}");
  if (!shapeOption(interp, "-axes",
                   [&] { dem::checkSemiAxes(e.axes->x(), e.axes->y(), "superquadric"); }) ||
      !shapeOption(interp, "-exponents",
                   [&] { dem::checkExponents(e.exponents->x(), e.exponents->y()); }))
    return TCL_ERROR;
  if (e.sides && *e.sides < 8) {  // the outline samples: the kernel takes no fewer than 8
    fail(interp, "VALUE SIDES",
         "-sides must be 8 to 10000 for a superquadric, got " + std::to_string(*e.sides));
    noteOptionOnce(interp, "-sides");
    return TCL_ERROR;
  }
  return guarded(interp, [&] {
    ElementDef def;
    def.shape = std::make_unique<dem::Superquadric>(e.axes->x(), e.axes->y(), e.exponents->x(),
                                                    e.exponents->y(), e.sides.value_or(32));
    def.x = *e.center;
    applyCommon(e, def);
    return create(interp, s, std::move(def));
  });
}

bool getElement(Tcl_Interp* interp, Tcl_Obj* obj, const dem::Assembly& a, int& slot) {
  int id = 0;
  if (!getInt(interp, obj, "ID", id)) return false;
  slot = a.bodies().slot(id);
  if (slot < 0) return reject(interp, "LOOKUP ELEMENT", "no element with id " + std::to_string(id));
  return true;
}

Tcl_Obj* holdValue(std::uint8_t h) {
  Tcl_Obj* l = Tcl_NewListObj(0, nullptr);
  const char* names[] = {"x", "y", "rot"};
  for (int k = 0; k < 3; ++k)
    if (h & (1u << k)) Tcl_ListObjAppendElement(nullptr, l, Tcl_NewStringObj(names[k], -1));
  return l;
}

Tcl_Obj* triple(const Vec2& v, double z) {
  Tcl_Obj* items[3] = {newDouble(v.x()), newDouble(v.y()), newDouble(z)};
  return Tcl_NewListObj(3, items);
}

Tcl_Obj* fieldValue(const dem::Assembly& a, int s, Field f) {
  const dem::Bodies& b = a.bodies();
  const dem::Shape& shape = *b.shape[s];
  switch (f) {
    case fCenter:
      return newVec2(b.x[s]);
    case fRadius:
      return shape.type() == ShapeType::disc
                 ? newDouble(static_cast<const dem::Disc&>(shape).radius())
                 : Tcl_NewObj();
    case fFrom:
    case fTo:
      if (shape.type() != ShapeType::wall) return Tcl_NewObj();
      {
        const auto [p, q] = static_cast<const dem::Wall&>(shape).ends(b.x[s], b.angle[s]);
        return newVec2(f == fFrom ? p : q);
      }
    case fThickness:
      return shape.type() == ShapeType::wall
                 ? newDouble(static_cast<const dem::Wall&>(shape).thickness())
                 : Tcl_NewObj();
    case fMaterial:
      return newString(a.materials()[b.material[s]].name);
    case fAngle:
      return newDouble(b.angle[s]);
    case fVelocity:
      return triple(b.v[s], b.w[s]);
    case fFix:
      return holdValue(b.hold[s]);
    case fForce:
      return triple(b.appliedForce[s], b.appliedTorque[s]);
    case fAcceleration:
      return newVec2(b.acceleration[s]);
    case fExponents:
      return Tcl_NewObj();
    case fStress:
      return std::isnan(b.stress[s]) ? Tcl_NewObj() : newDouble(b.stress[s]);
    case fVertices:
    case fAxes:
    case fSides:
      return Tcl_NewObj();  // creation-only; element info lists a polygon's vertices
    case fId:
      return Tcl_NewIntObj(b.id[s]);
  }
  return Tcl_NewObj();
}

int ElementConfigure(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  Session& s = sessionOf(data);
  dem::Assembly& a = s.manager.assembly();
  if (objc < 2) {
    Tcl_WrongNumArgs(interp, 1, objv, "ID ?-option value ...?");
    return TCL_ERROR;
  }
  int slot = 0;
  if (!getElement(interp, objv[1], a, slot)) return TCL_ERROR;
  const Table& table = configureTable();
  if (objc <= 3) {
    if (objc == 3) {
      const int k = optionIndex(interp, objv[2], table.specs.data());
      if (k < 0) return TCL_ERROR;
      Tcl_SetObjResult(interp, fieldValue(a, slot, table.fields[k]));
      return TCL_OK;
    }
    Tcl_Obj* all = Tcl_NewListObj(0, nullptr);
    for (std::size_t k = 0; k < table.fields.size(); ++k) {
      Tcl_ListObjAppendElement(nullptr, all, Tcl_NewStringObj(table.specs[k].name, -1));
      Tcl_ListObjAppendElement(nullptr, all, fieldValue(a, slot, table.fields[k]));
    }
    Tcl_SetObjResult(interp, all);
    return TCL_OK;
  }
  if (objc % 2) {
    Tcl_WrongNumArgs(interp, 1, objv, "ID ?-option value ...?");
    return TCL_ERROR;
  }
  Edit e;
  if (!parseEdit(interp, objc, objv, 2, table, a, e)) return TCL_ERROR;
  dem::ElementEdit edit;
  edit.center = e.center, edit.angle = e.angle, edit.from = e.from, edit.to = e.to;
  edit.radius = e.radius, edit.material = e.material, edit.velocity = e.velocity;
  edit.force = e.force, edit.acceleration = e.acceleration, edit.hold = e.hold;
  edit.stress = e.stress;
  try {
    a.configure(a.bodies().id[slot], edit);
  } catch (const Error& error) {
    fail(interp, error);
    // The kernel names the field; errorInfo names the option.
    const std::string& code = error.code();
    const char* option = code == "VALUE RADIUS"   ? "-radius"
                         : code == "VALUE STRESS" ? "-stress"
                         : code == "VALUE WALL"   ? (e.from ? "-from" : "-to")
                         : code == "VALUE MASS"   ? (e.radius     ? "-radius"
                                                     : e.material ? "-material"
                                                                  : nullptr)
                                                  : nullptr;
    if (option) noteOptionOnce(interp, option);
    return TCL_ERROR;
  }
  return TCL_OK;
}

int ElementCget(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  const dem::Assembly& a = sessionOf(data).manager.assembly();
  if (objc != 3) {
    Tcl_WrongNumArgs(interp, 1, objv, "ID -option");
    return TCL_ERROR;
  }
  int slot = 0;
  if (!getElement(interp, objv[1], a, slot)) return TCL_ERROR;
  const Table& table = configureTable();
  const int k = optionIndex(interp, objv[2], table.specs.data());
  if (k < 0) return TCL_ERROR;
  Tcl_SetObjResult(interp, fieldValue(a, slot, table.fields[k]));
  return TCL_OK;
}

int ElementInfo(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  const dem::Assembly& a = sessionOf(data).manager.assembly();
  if (objc != 2) {
    Tcl_WrongNumArgs(interp, 1, objv, "ID");
    return TCL_ERROR;
  }
  int s = 0;
  if (!getElement(interp, objv[1], a, s)) return TCL_ERROR;
  const dem::Bodies& b = a.bodies();
  int contacts = 0;
  // By id: after a deletion the list keeps old slots (and the deleted
  // element's contacts) until the next step's pair search.
  for (const dem::Contact& c : a.contacts())
    contacts += c.touching && ((c.idA == b.id[s] && b.slot(c.idB) >= 0) ||
                               (c.idB == b.id[s] && b.slot(c.idA) >= 0));
  const dem::Shape& shape = *b.shape[s];
  Tcl_Obj* d = newDict({{"id", Tcl_NewIntObj(b.id[s])},
                        {"type", Tcl_NewStringObj(dem::shapeTypeNames[int(shape.type())], -1)},
                        {"position", newVec2(b.x[s])},
                        {"angle", newDouble(b.angle[s])},
                        {"velocity", triple(b.v[s], b.w[s])},
                        {"force", newVec2(b.force[s])},
                        {"torque", newDouble(b.torque[s])},
                        {"mass", newDouble(b.mass[s])},
                        {"inertia", newDouble(b.inertia[s])},
                        {"area", newDouble(shape.area())},
                        {"material", fieldValue(a, s, fMaterial)},
                        {"fix", holdValue(b.hold[s])},
                        {"applied", triple(b.appliedForce[s], b.appliedTorque[s])},
                        {"acceleration", newVec2(b.acceleration[s])},
                        {"contacts", Tcl_NewIntObj(contacts)},
                        {"contactforce", newVec2(a.contactForce(s))},
                        {"fluidforce", newVec2(b.fluidForce[s])},
                        {"fluidtorque", newDouble(b.fluidTorque[s])},
                        {"buoyancy", newVec2(b.buoyancy[s])}});
  if (shape.type() == ShapeType::disc) dictPut(d, "radius", fieldValue(a, s, fRadius));
  if (shape.type() == ShapeType::polygon) {
    Tcl_Obj* v = Tcl_NewListObj(0, nullptr);
    for (const Vec2& p : static_cast<const dem::Polygon&>(shape).world(b.x[s], b.angle[s])) {
      Tcl_ListObjAppendElement(nullptr, v, newDouble(p.x()));
      Tcl_ListObjAppendElement(nullptr, v, newDouble(p.y()));
    }
    dictPut(d, "vertices", v);
  }
  if (shape.type() == ShapeType::superquadric) {
    const auto& q = static_cast<const dem::Superquadric&>(shape);
    dictPut(d, "axes", newVec2(Vec2(q.a(), q.b())));
    dictPut(d, "exponents", newVec2(Vec2(q.m(), q.n())));
    dictPut(d, "sides", Tcl_NewIntObj(q.samples()));
  }
  if (shape.type() == ShapeType::wall) {
    dictPut(d, "from", fieldValue(a, s, fFrom));
    dictPut(d, "to", fieldValue(a, s, fTo));
  }
  Tcl_SetObjResult(interp, d);
  return TCL_OK;
}

int ElementIds(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  const dem::Assembly& a = sessionOf(data).manager.assembly();
  static const OptionSpec options[] = {
      {"-type", "disc|polygon|superquadric|wall", "only this shape"}, {nullptr, nullptr, nullptr}};
  if (objc != 1 && objc != 3) {
    Tcl_WrongNumArgs(interp, 1, objv, "?-type disc|polygon|superquadric|wall?");
    return TCL_ERROR;
  }
  int type = -1;
  if (objc == 3) {
    if (optionIndex(interp, objv[1], options) < 0) return TCL_ERROR;
    if (!getChoice(interp, objv[2], "type", dem::shapeTypeNames, type)) return TCL_ERROR;
  }
  std::vector<int> ids;
  for (int s = 0; s < a.bodies().size(); ++s)
    if (type < 0 || int(a.bodies().shape[s]->type()) == type) ids.push_back(a.bodies().id[s]);
  std::sort(ids.begin(), ids.end());
  Tcl_Obj* l = Tcl_NewListObj(0, nullptr);
  for (int id : ids) Tcl_ListObjAppendElement(nullptr, l, Tcl_NewIntObj(id));
  Tcl_SetObjResult(interp, l);
  return TCL_OK;
}

int ElementDelete(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  dem::Assembly& a = sessionOf(data).manager.assembly();
  if (objc != 2) {
    Tcl_WrongNumArgs(interp, 1, objv, "ID");
    return TCL_ERROR;
  }
  int s = 0;
  if (!getElement(interp, objv[1], a, s)) return TCL_ERROR;
  a.remove(a.bodies().id[s]);
  return TCL_OK;
}

int ElementNext(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc != 1) {
    Tcl_WrongNumArgs(interp, 1, objv, nullptr);
    return TCL_ERROR;
  }
  return guarded(interp, [&] {
    Tcl_SetObjResult(interp, Tcl_NewIntObj(sessionOf(data).manager.assembly().nextId()));
    return TCL_OK;
  });
}

int helpFor(Tcl_Interp* interp, int objc, Tcl_Obj* const objv[], const char* noun,
            std::initializer_list<const char*> verbs, const Table& table) {
  if (objc != 1) {
    Tcl_WrongNumArgs(interp, 1, objv, nullptr);
    return TCL_ERROR;
  }
  Tcl_SetObjResult(interp, newString(helpText(noun, verbs, table.specs.data())));
  return TCL_OK;
}

int DiscHelp(ClientData, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  return helpFor(interp, objc, objv, "disc",
                 {"create -center {x y} -radius r ?-option value ...?   -> id", "help"},
                 discTable());
}
int WallHelp(ClientData, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  return helpFor(interp, objc, objv, "wall",
                 {"create -from {x y} -to {x y} ?-option value ...?   -> id", "help"}, wallTable());
}
int PolygonHelp(ClientData, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  return helpFor(interp, objc, objv, "polygon",
                 {"create -vertices {x1 y1 x2 y2 ...} ?-option value ...?   -> id", "help"},
                 polygonTable());
}
int EllipseHelp(ClientData, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  return helpFor(interp, objc, objv, "ellipse",
                 {"create -center {x y} -axes {a b} ?-sides N? ?-option value ...?   -> id "
                  "(an N-sided polygon)",
                  "help"},
                 ellipseTable());
}
int SuperquadricHelp(ClientData, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  return helpFor(interp, objc, objv, "superquadric",
                 {"create -center {x y} -axes {a b} -exponents {m n} ?-sides N? ?-option value "
                  "...?   -> id (outline sampled at N points, default 32)",
                  "help"},
                 superquadricTable());
}
int ElementHelp(ClientData, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  return helpFor(interp, objc, objv, "element",
                 {"configure ID ?-option value ...?", "cget ID -option",
                  "info ID   -> dict type position angle velocity force torque mass inertia ...",
                  "ids ?-type disc|polygon|superquadric|wall?", "delete ID",
                  "next      -> the next free id", "help"},
                 configureTable());
}

}  // namespace

void registerElementCommands(Tcl_Interp* interp, Session* session) {
  makeEnsemble(interp, "::sf::disc", {{"create", DiscCreate}, {"help", DiscHelp}}, session);
  makeEnsemble(interp, "::sf::wall", {{"create", WallCreate}, {"help", WallHelp}}, session);
  makeEnsemble(interp, "::sf::polygon", {{"create", PolygonCreate}, {"help", PolygonHelp}},
               session);
  makeEnsemble(interp, "::sf::superquadric",
               {{"create", SuperquadricCreate}, {"help", SuperquadricHelp}}, session);
  makeEnsemble(interp, "::sf::ellipse", {{"create", EllipseCreate}, {"help", EllipseHelp}},
               session);
  makeEnsemble(interp, "::sf::element",
               {{"configure", ElementConfigure},
                {"cget", ElementCget},
                {"info", ElementInfo},
                {"ids", ElementIds},
                {"delete", ElementDelete},
                {"next", ElementNext},
                {"help", ElementHelp}},
               session);
}

}  // namespace sf::tcl
