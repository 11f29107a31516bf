// disc, wall, polygon, ellipse, superquadric: create and help
#include <cmath>
#include <numbers>
#include <optional>

#include "element_options.hpp"
#include "sandflow/dem/polygon.hpp"
#include "sandflow/dem/shape_checks.hpp"
#include "sandflow/dem/superquadric.hpp"
#include "sandflow/tcl/args.hpp"
#include "sandflow/tcl/session.hpp"

namespace sf::tcl {
namespace {

using dem::ElementDef;
using dem::ShapeType;

// The options from objv[1..), converted and range-checked by the table's rows.
bool parseCreate(Tcl_Interp* interp, int objc, Tcl_Obj* const objv[], const ElementTable& table,
                 const dem::Assembly& assembly, ElementDraft& e) {
  e.materials = &assembly.materials();
  return table.apply(interp, objc, objv, 1, e);
}

// Settings shared by every shape, onto a definition.
void applyCommon(const ElementDraft& e, ElementDef& def) {
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
  ElementDraft e;
  if (!parseCreate(interp, objc, objv, discOptions(), s.manager.assembly(), e)) return TCL_ERROR;
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
  ElementDraft e;
  if (!parseCreate(interp, objc, objv, wallOptions(), s.manager.assembly(), e)) return TCL_ERROR;
  ElementDef def;
  if (e.center || e.length) {  // the wall's own pose: centre, length and angle
    if (e.from || e.to)
      return fail(interp, "VALUE WALL",
                  "wall create takes -from and -to, or -center and -length: not both");
    if (!e.center || !e.length)
      return fail(interp, "VALUE WALL", "wall create needs -center {x y} with -length L");
    def.shape = std::make_unique<dem::Wall>(
        *e.length, e.thickness.value_or(dem::Wall::defaultThickness(*e.length)));
    def.x = *e.center;  // and -angle, as for any shape (applyCommon)
  } else {
    if (!e.from || !e.to)
      return fail(interp, "VALUE WALL", "wall create needs -from {x y} and -to {x y}");
    const Vec2 seg = *e.to - *e.from;
    if (!(seg.norm() > 0))
      return fail(interp, "VALUE WALL", "wall has zero length: -from equals -to");
    if (e.angle) return fail(interp, "VALUE ANGLE", "a wall's angle follows from -from and -to");
    def.shape = std::make_unique<dem::Wall>(
        seg.norm(), e.thickness.value_or(dem::Wall::defaultThickness(seg.norm())));
    def.x = 0.5 * (*e.from + *e.to);
    def.angle = std::atan2(seg.y(), seg.x());
  }
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
  ElementDraft e;
  if (!parseCreate(interp, objc, objv, polygonOptions(), s.manager.assembly(), e)) return TCL_ERROR;
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
  ElementDraft e;
  if (!parseCreate(interp, objc, objv, ellipseOptions(), s.manager.assembly(), e)) return TCL_ERROR;
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
  ElementDraft e;
  if (!parseCreate(interp, objc, objv, superquadricOptions(), s.manager.assembly(), e))
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
  return guarded(interp, [&] {
    ElementDef def;
    def.shape = std::make_unique<dem::Superquadric>(e.axes->x(), e.axes->y(), e.exponents->x(),
                                                    e.exponents->y(), e.sides.value_or(32));
    def.x = *e.center;
    applyCommon(e, def);
    return create(interp, s, std::move(def));
  });
}

int helpFor(Tcl_Interp* interp, int objc, Tcl_Obj* const objv[], const char* noun,
            const char* create, const ElementTable& table, ShapeType shape) {
  if (objc != 1) {
    Tcl_WrongNumArgs(interp, 1, objv, nullptr);
    return TCL_ERROR;
  }
  Tcl_SetObjResult(interp,
                   newString(table.help(noun, {create, "help"}, ElementDraft::defaults(shape))));
  return TCL_OK;
}

int DiscHelp(ClientData, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  return helpFor(interp, objc, objv, "disc",
                 "create -center {x y} -radius r ?-option value ...?   -> id", discOptions(),
                 ShapeType::disc);
}
int WallHelp(ClientData, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  return helpFor(interp, objc, objv, "wall",
                 "create -from {x y} -to {x y} ?-option value ...?   -> id\n"
                 "wall create -center {x y} -length L ?-angle a? ?-option value ...?   -> id",
                 wallOptions(), ShapeType::wall);
}
int PolygonHelp(ClientData, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  return helpFor(interp, objc, objv, "polygon",
                 "create -vertices {x1 y1 x2 y2 ...} ?-option value ...?   -> id", polygonOptions(),
                 ShapeType::polygon);
}
int EllipseHelp(ClientData, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  return helpFor(interp, objc, objv, "ellipse",
                 "create -center {x y} -axes {a b} ?-sides N? ?-option value ...?   -> id "
                 "(an N-sided polygon)",
                 ellipseOptions(), ShapeType::polygon);
}
int SuperquadricHelp(ClientData, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  return helpFor(interp, objc, objv, "superquadric",
                 "create -center {x y} -axes {a b} -exponents {m n} ?-sides N? ?-option value "
                 "...?   -> id (outline sampled at N points, default 32)",
                 superquadricOptions(), ShapeType::superquadric);
}

}  // namespace

void registerShapeCommands(Tcl_Interp* interp, Session* session) {
  makeEnsemble(interp, "::sf::disc", {{"create", DiscCreate}, {"help", DiscHelp}}, session);
  makeEnsemble(interp, "::sf::wall", {{"create", WallCreate}, {"help", WallHelp}}, session);
  makeEnsemble(interp, "::sf::polygon", {{"create", PolygonCreate}, {"help", PolygonHelp}},
               session);
  makeEnsemble(interp, "::sf::superquadric",
               {{"create", SuperquadricCreate}, {"help", SuperquadricHelp}}, session);
  makeEnsemble(interp, "::sf::ellipse", {{"create", EllipseCreate}, {"help", EllipseHelp}},
               session);
}

}  // namespace sf::tcl
