// lattice create|configure|cget|info|probe|obstacle|obstacles|delete|help
#include <array>
#include <cmath>

#include "lattice_sides.hpp"
#include "sandflow/tcl/args.hpp"
#include "sandflow/tcl/option_table.hpp"
#include "sandflow/tcl/session.hpp"

namespace sf::tcl {
namespace {

using lb::LatticeDef;
using lb::SideKind;

const char* const kCollisionNames[] = {"bgk", "trt", nullptr};
const char* const kForceSchemeNames[] = {"nodal", "guo", nullptr};

// What lattice create and configure set, staged; with the resolved values
// that cget reports.
struct LatticeDraft {
  LatticeDef def;
  int nx = 0;
  double h = 0, viscosity = 0, tau = 0;

  static LatticeDraft of(const lb::ResolvedLattice& p) {
    LatticeDraft s{p.def, p.nx, p.h, p.viscosity, p.tau};
    s.def.viscosity = p.viscosity, s.def.tau = p.tau, s.def.timestep = p.dt;
    s.def.cells = p.nx, s.def.spacing = 0;
    return s;
  }
};

using Row = Option<LatticeDraft>;
// In this order: -periodic is applied before -walls.
const OptionTable<LatticeDraft> kOptions{
    {Row{.info = {.name = "-origin",
                  .synopsis = "{x0 y0}",
                  .help = "lower-left corner",
                  .kind = ValueKind::vec2,
                  .unit = "length"},
         .get = [](const LatticeDraft& s) { return vecValue(s.def.origin); },
         .set = [](LatticeDraft& s, const OptionValue& v) { s.def.origin = v.vec; }},
     Row{.info = {.name = "-size",
                  .synopsis = "{Lx Ly}",
                  .help = "width and height, whole numbers of spacings",
                  .kind = ValueKind::vec2,
                  .unit = "length",
                  .range = {.min = 0, .minOpen = true},
                  .defaultText = ""},
         .get = [](const LatticeDraft& s) { return vecValue(s.def.size); },
         .set = [](LatticeDraft& s, const OptionValue& v) { s.def.size = v.vec; }},
     Row{.info = {.name = "-cells",
                  .synopsis = "NX",
                  .help = "cells across x (or give -spacing)",
                  .kind = ValueKind::integer,
                  .range = {.min = 1},
                  .defaultText = ""},
         .get = [](const LatticeDraft& s) { return integerValue(s.nx); },
         .set = [](LatticeDraft& s,
                   const OptionValue& v) { s.def.cells = v.integer, s.def.spacing = 0; }},
     Row{.info = {.name = "-spacing",
                  .synopsis = "h",
                  .help = "node spacing (or give -cells)",
                  .unit = "length",
                  .range = {.min = 0, .minOpen = true},
                  .defaultText = ""},
         .get = [](const LatticeDraft& s) { return realValue(s.h); },
         .set = [](LatticeDraft& s,
                   const OptionValue& v) { s.def.spacing = v.real, s.def.cells = 0; }},
     Row{.info = {.name = "-viscosity",
                  .synopsis = "nu",
                  .help = "kinematic viscosity; with tau it sets the timestep",
                  .unit = "length^2/time",
                  .range = {.min = 0, .minOpen = true},
                  .defaultText = ""},
         .get = [](const LatticeDraft& s) { return realValue(s.viscosity); },
         .set = [](LatticeDraft& s, const OptionValue& v) { s.def.viscosity = v.real; }},
     Row{.info = {.name = "-density",
                  .synopsis = "rho0",
                  .help = "initial and reference density",
                  .unit = "mass/length^2",
                  .range = {.min = 0, .minOpen = true}},
         .get = [](const LatticeDraft& s) { return realValue(s.def.density); },
         .set = [](LatticeDraft& s, const OptionValue& v) { s.def.density = v.real; }},
     Row{.info = {.name = "-tau",
                  .synopsis = "tau",
                  .help = "relaxation time (a fixed sim -timestep sets it instead)",
                  .range = {.min = lb::kTauMin, .minOpen = true},
                  .outOfRange = lb::unstableTau,
                  .defaultText = "1"},
         .get = [](const LatticeDraft& s) { return realValue(s.tau); },
         .set = [](LatticeDraft& s, const OptionValue& v) { s.def.tau = v.real; }},
     Row{.info = {.name = "-periodic",
                  .synopsis = "{x y}",
                  .help = "periodic axes: two booleans, or axis names",
                  .kind = ValueKind::custom},
         .parse = [](Tcl_Interp* interp, Tcl_Obj* v,
                     LatticeDraft& s) { return parsePeriodic(interp, v, s.def); },
         .show =
             [](const LatticeDraft& s) {
               Tcl_Obj* flags[2] = {
                   Tcl_NewBooleanObj(s.def.sides[lb::left].kind == SideKind::periodic),
                   Tcl_NewBooleanObj(s.def.sides[lb::bottom].kind == SideKind::periodic)};
               return Tcl_NewListObj(2, flags);
             }},
     Row{.info = {.name = "-walls",
                  .synopsis = "{side kind ...}",
                  .help = "sides left right bottom top: noslip ?{vx vy}?, slip, periodic, "
                          "velocity {vx vy} ?-profile uniform|parabolic? ?-ramp T?, velocity "
                          "-expr {EXPR_X EXPR_Y} ?-ramp T?, pressure p, outflow",
                  .kind = ValueKind::custom},
         .parse = [](Tcl_Interp* interp, Tcl_Obj* v,
                     LatticeDraft& s) { return parseWalls(interp, v, s.def); },
         .show = [](const LatticeDraft& s) { return wallsValue(s.def); }},
     Row{.info = {.name = "-forcing",
                  .synopsis = "{Fx Fy}",
                  .help = "body force per unit area (rho a)",
                  .kind = ValueKind::vec2,
                  .unit = "mass/(length time^2)"},
         .get = [](const LatticeDraft& s) { return vecValue(s.def.forcing); },
         .set = [](LatticeDraft& s, const OptionValue& v) { s.def.forcing = v.vec; }},
     Row{.info = {.name = "-collision",
                  .synopsis = "bgk|trt",
                  .help = "collision operator",
                  .kind = ValueKind::choice,
                  .choices = kCollisionNames,
                  .what = "collision"},
         .get = [](const LatticeDraft& s) { return choiceValue(int(s.def.collision)); },
         .set = [](LatticeDraft& s,
                   const OptionValue& v) { s.def.collision = lb::Collision(v.choice); }},
     Row{.info = {.name = "-forcescheme",
                  .synopsis = "nodal|guo",
                  .help = "body-force scheme (nodal: the thesis's)",
                  .kind = ValueKind::choice,
                  .choices = kForceSchemeNames,
                  .what = "force scheme"},
         .get = [](const LatticeDraft& s) { return choiceValue(int(s.def.forceScheme)); },
         .set = [](LatticeDraft& s,
                   const OptionValue& v) { s.def.forceScheme = lb::ForceScheme(v.choice); }},
     Row{.info = {.name = "-magic",
                  .synopsis = "Lambda",
                  .help = "TRT magic parameter (0.1875: walls exactly halfway)",
                  .range = {.min = 0, .minOpen = true}},
         .get = [](const LatticeDraft& s) { return realValue(s.def.magic); },
         .set = [](LatticeDraft& s, const OptionValue& v) { s.def.magic = v.real; }}},
    true};
// The rows whose presence the commands read (the table's own order aside).
const int kSize = kOptions.index("-size"), kCells = kOptions.index("-cells"),
          kSpacing = kOptions.index("-spacing"), kViscosity = kOptions.index("-viscosity"),
          kTau = kOptions.index("-tau");

// A new lattice's settings, for help's and `lattice options`' defaults.
const LatticeDraft& defaults() {
  static const LatticeDraft d = [] {
    LatticeDraft s;
    s.tau = 1;
    return s;
  }();
  return d;
}

// The settings the lattice was given, of those the kernel can derive from
// others (the spacing from the cells or back, one of viscosity, tau and
// timestep from the other two): their options, the rest being derived.
Tcl_Obj* givenSettings(const LatticeDef& def) {
  Tcl_Obj* given = Tcl_NewListObj(0, nullptr);
  auto add = [&](bool was, const char* option) {
    if (was) Tcl_ListObjAppendElement(nullptr, given, Tcl_NewStringObj(option, -1));
  };
  add(def.cells > 0, "-cells");
  add(def.spacing > 0, "-spacing");
  add(def.viscosity.has_value(), "-viscosity");
  add(def.tau.has_value(), "-tau");
  add(def.timestep.has_value() && !(def.viscosity && def.tau), "-timestep");
  return given;
}

int LatticeCreate(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  Session& s = sessionOf(data);
  if (objc < 2 || objc % 2 == 0) {
    Tcl_WrongNumArgs(interp, 1, objv, "-size {Lx Ly} (-cells NX | -spacing h) ?-option value ...?");
    return TCL_ERROR;
  }
  LatticeDraft draft;
  std::vector<bool> given;
  if (!kOptions.apply(interp, objc, objv, 1, draft, &given)) return TCL_ERROR;
  const LatticeDef& def = draft.def;
  if (!given[kSize]) return fail(interp, "VALUE SIZE", "lattice create needs -size {Lx Ly}");
  if (given[kCells] == given[kSpacing])
    return fail(interp, "VALUE CELLS", "lattice create needs exactly one of -cells and -spacing");
  const int code = guarded(interp, [&] {
    evaluateSideExpressions(interp, draft.def, s.manager.time());
    s.manager.createLattice(def);
    return TCL_OK;
  });
  flushWarnings(s);  // told now (BGK at tau 3 along walls), not at the first step
  return code;
}

int LatticeConfigure(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  Session& s = sessionOf(data);
  const int code = guarded(interp, [&] {
    LatticeDraft draft = LatticeDraft::of(s.manager.lattice().params());
    if (objc == 1) {
      Tcl_SetObjResult(interp, kOptions.all(draft));
      return TCL_OK;
    }
    if (objc == 2) {  // like Tk: "configure -option" reports that option
      const int k = optionIndex(interp, objv[1], kOptions.specs());
      if (k < 0) return TCL_ERROR;
      Tcl_SetObjResult(interp, kOptions.get(draft, k));
      return TCL_OK;
    }
    if (objc % 2 == 0) {
      Tcl_WrongNumArgs(interp, 1, objv, "?-option value ...?");
      return TCL_ERROR;
    }
    std::vector<bool> given;
    if (!kOptions.apply(interp, objc, objv, 1, draft, &given)) return TCL_ERROR;
    LatticeDef& def = draft.def;  // (a new density: the kernel refuses it)
    // Keep the timestep unless tau is what changed. Neither given: the two
    // of viscosity, tau and timestep the lattice was given, not all three
    // resolved (which would give the timestep again to the last bit or not).
    const LatticeDef& was = s.manager.lattice().params().def;
    if (!given[kViscosity] && !given[kTau])
      def.viscosity = was.viscosity, def.tau = was.tau, def.timestep = was.timestep;
    if (given[kViscosity] && !given[kTau]) def.tau.reset();
    if (given[kTau]) def.timestep.reset();
    evaluateSideExpressions(interp, def, s.manager.time());
    s.manager.reconfigureLattice(def);
    return TCL_OK;
  });
  flushWarnings(s);
  return code;
}

int LatticeCget(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  Session& s = sessionOf(data);
  if (objc != 2) {
    Tcl_WrongNumArgs(interp, 1, objv, "-option");
    return TCL_ERROR;
  }
  return guarded(interp, [&] {
    const LatticeDraft draft = LatticeDraft::of(s.manager.lattice().params());
    const int k = optionIndex(interp, objv[1], kOptions.specs());
    if (k < 0) return TCL_ERROR;
    Tcl_SetObjResult(interp, kOptions.get(draft, k));
    return TCL_OK;
  });
}

int LatticeInfo(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  Session& s = sessionOf(data);
  if (objc != 1) {
    Tcl_WrongNumArgs(interp, 1, objv, nullptr);
    return TCL_ERROR;
  }
  return guarded(interp, [&] {
    const lb::Lattice& l = s.manager.lattice();
    const lb::ResolvedLattice& p = l.params();
    Tcl_Obj* kinds = Tcl_NewDictObj();
    for (const auto& k : l.kinds())
      dictPut(kinds, k->name(), Tcl_NewWideIntObj(Tcl_WideInt(k->count())));
    Tcl_SetObjResult(
        interp,
        newDict({{"nx", Tcl_NewIntObj(p.nx)},
                 {"ny", Tcl_NewIntObj(p.ny)},
                 {"nodes", Tcl_NewWideIntObj(Tcl_WideInt(l.nodes()))},
                 {"spacing", newDouble(p.h)},
                 {"timestep", newDouble(p.dt)},
                 {"tau", newDouble(p.tau)},
                 {"viscosity", newDouble(p.viscosity)},
                 {"c", newDouble(p.latticeSpeed())},
                 {"cs", newDouble(p.soundSpeed())},
                 {"mach", newDouble(l.maxMach())},
                 {"mass", newDouble(l.mass())},
                 {"momentum", newVec2(l.momentum())},
                 {"density", newDouble(p.def.density)},
                 {"origin", newVec2(p.def.origin)},
                 {"size", newVec2(p.def.size)},
                 {"forcing", newVec2(p.def.forcing)},
                 {"collision", Tcl_NewStringObj(kCollisionNames[int(p.def.collision)], -1)},
                 {"forcescheme", Tcl_NewStringObj(kForceSchemeNames[int(p.def.forceScheme)], -1)},
                 {"magic", newDouble(p.def.magic)},
                 {"walls", wallsValue(p.def)},
                 {"kinds", kinds},
                 {"threads", Tcl_NewIntObj(l.threads())},
                 {"memory", Tcl_NewWideIntObj(Tcl_WideInt(l.memoryBytes()))},
                 {"bytespernode", newDouble(double(l.memoryBytes()) / double(l.nodes()))},
                 {"given", givenSettings(p.def)}}));
    return TCL_OK;
  });
}

int LatticeProbe(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  Session& s = sessionOf(data);
  if (objc != 2) {
    Tcl_WrongNumArgs(interp, 1, objv, "{x y}");
    return TCL_ERROR;
  }
  Vec2 x;
  if (!getVec2(interp, objv[1], "point", x)) return TCL_ERROR;
  return guarded(interp, [&] {
    const lb::Lattice& l = s.manager.lattice();
    const auto node = l.nodeAt(x);
    if (!node)
      return fail(
          interp, "VALUE POINT",
          "point {" + formatNumber(x.x()) + " " + formatNumber(x.y()) + "} is outside the lattice");
    const auto [i, j] = *node;
    static const char* const kindNames[] = {"fluid",    "noslip",   "slip", "solid",
                                            "velocity", "pressure", "open"};
    const lb::NodeKind k = l.kind(i, j);
    const bool wall =
        k == lb::NodeKind::noslip || k == lb::NodeKind::slip || k == lb::NodeKind::solid;
    Tcl_Obj* ij[2] = {Tcl_NewIntObj(i), Tcl_NewIntObj(j)};
    // solid: 1 on fixed walls, else the solid ratio that moving solids gave the
    // cell in the last step.
    Tcl_SetObjResult(interp, newDict({{"density", newDouble(l.density(i, j))},
                                      {"pressure", newDouble(l.pressure(i, j))},
                                      {"velocity", newVec2(l.velocity(i, j))},
                                      {"solid", newDouble(wall ? 1.0 : l.solidRatio(i, j))},
                                      {"solidvelocity", newVec2(l.solidVelocity(i, j))},
                                      {"kind", Tcl_NewStringObj(kindNames[int(k)], -1)},
                                      {"node", Tcl_NewListObj(2, ij)},
                                      {"position", newVec2(l.position(i, j))}}));
    return TCL_OK;
  });
}

int LatticeDelete(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  Session& s = sessionOf(data);
  if (objc != 1) {
    Tcl_WrongNumArgs(interp, 1, objv, nullptr);
    return TCL_ERROR;
  }
  return guarded(interp, [&] {
    s.manager.deleteLattice();
    return TCL_OK;
  });
}

// ---- obstacles ---------------------------------------------------------------

// An obstacle's -id: >= 0, or the next free one when not given (the
// kernel's -1).
template <class Obstacle>
Option<Obstacle> idRow() {
  return {.info = {.name = "-id",
                   .synopsis = "N",
                   .help = "the obstacle's id",
                   .kind = ValueKind::integer,
                   .range = {.min = 0},
                   .defaultText = "the next free one"},
          .get = [](const Obstacle& o) { return integerValue(o.id); },
          .set = [](Obstacle& o, const OptionValue& v) { o.id = v.integer; }};
}

const OptionTable<lb::RectObstacle> kRectOptions{
    memberRow({.name = "-slip",
               .synopsis = "0|1",
               .help = "specular (free-slip) walls instead of no-slip"},
              &lb::RectObstacle::slip),
    idRow<lb::RectObstacle>()};

const OptionTable<lb::CircleObstacle> kCircleOptions{
    memberRow({.name = "-outside",
               .synopsis = "0|1",
               .help = "solid outside the circle instead of inside: a container"},
              &lb::CircleObstacle::outside),
    {.info = {.name = "-velocity",
              .synopsis = "{vx vy w}",
              .help = "translation and rotation rate of the wall",
              .kind = ValueKind::vec3,
              .unit = "length/time, 1/time"},
     .get =
         [](const lb::CircleObstacle& c) {
           return vec3Value({c.velocity.x(), c.velocity.y(), c.spin});
         },
     .set =
         [](lb::CircleObstacle& c, const OptionValue& v) {
           c.velocity = Vec2(v.vec3.x(), v.vec3.y());
           c.spin = v.vec3.z();
         }},
    idRow<lb::CircleObstacle>()};

// The defaults the tables' help shows: an obstacle given no option.
template <class Obstacle>
Obstacle defaultObstacle() {
  Obstacle o;
  o.id = -1;
  return o;
}

// lattice obstacle rect|circle GEOMETRY ?-option value ...? -> id; the
// geometry ({x0 y0 x1 y1} or {cx cy r}) is checked by the kernel.
template <class Obstacle>
int addObstacle(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[],
                const char* geometry, int numbers, const OptionTable<Obstacle>& options,
                const std::function<void(const std::vector<double>&, Obstacle&)>& place,
                int (lb::Lattice::*add)(const Obstacle&)) {
  Session& s = sessionOf(data);
  if (objc < 2 || objc % 2 == 1) {
    std::string usage = std::string(geometry);
    for (int k = 0; k < options.size(); ++k)
      usage += std::string(" ?") + options.info(k).name + " " + options.info(k).synopsis + "?";
    Tcl_WrongNumArgs(interp, 1, objv, usage.c_str());
    return TCL_ERROR;
  }
  std::vector<double> numbersGiven;
  if (!getDoubles(interp, objv[1], numbers == 4 ? "rect" : "circle", numbers, numbersGiven))
    return TCL_ERROR;
  Obstacle o = defaultObstacle<Obstacle>();
  place(numbersGiven, o);
  if (!options.apply(interp, objc, objv, 2, o)) return TCL_ERROR;
  return guarded(interp, [&] {
    Tcl_SetObjResult(interp, Tcl_NewIntObj((s.manager.lattice().*add)(o)));
    return TCL_OK;
  });
}

int ObstacleRect(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  return addObstacle<lb::RectObstacle>(
      data, interp, objc, objv, "{x0 y0 x1 y1}", 4, kRectOptions,
      [](const std::vector<double>& b, lb::RectObstacle& r) {
        r.lo = Vec2(b[0], b[1]);
        r.hi = Vec2(b[2], b[3]);
      },
      &lb::Lattice::addObstacle);
}

int ObstacleCircle(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  return addObstacle<lb::CircleObstacle>(
      data, interp, objc, objv, "{cx cy r}", 3, kCircleOptions,
      [](const std::vector<double>& c, lb::CircleObstacle& o) {
        o.centre = Vec2(c[0], c[1]);
        o.radius = c[2];
      },
      &lb::Lattice::addCircle);
}

int ObstacleDelete(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  int id = 0;
  if (!getSoleId(interp, objc, objv, "ID", id)) return TCL_ERROR;
  return guarded(interp, [&] {
    sessionOf(data).manager.lattice().deleteObstacle(id);
    return TCL_OK;
  });
}

int ObstacleInfo(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  int id = 0;
  if (!getSoleId(interp, objc, objv, "ID", id)) return TCL_ERROR;
  return guarded(interp, [&] {
    const lb::ObstacleInfo o = sessionOf(data).manager.lattice().obstacleInfo(id);
    if (o.circle) {
      const lb::CircleObstacle& c = o.disc;
      Tcl_Obj* circle[3] = {newDouble(c.centre.x()), newDouble(c.centre.y()), newDouble(c.radius)};
      Tcl_Obj* velocity[3] = {newDouble(c.velocity.x()), newDouble(c.velocity.y()),
                              newDouble(c.spin)};
      Tcl_SetObjResult(interp, newDict({{"id", Tcl_NewIntObj(c.id)},
                                        {"type", Tcl_NewStringObj("circle", -1)},
                                        {"circle", Tcl_NewListObj(3, circle)},
                                        {"outside", Tcl_NewBooleanObj(c.outside)},
                                        {"velocity", Tcl_NewListObj(3, velocity)},
                                        {"cells", Tcl_NewWideIntObj(Tcl_WideInt(c.cells))},
                                        {"force", newVec2(o.force)},
                                        {"torque", newDouble(o.torque)}}));
      return TCL_OK;
    }
    Tcl_Obj* rect[4] = {newDouble(o.rect.lo.x()), newDouble(o.rect.lo.y()),
                        newDouble(o.rect.hi.x()), newDouble(o.rect.hi.y())};
    Tcl_SetObjResult(interp, newDict({{"id", Tcl_NewIntObj(o.rect.id)},
                                      {"type", Tcl_NewStringObj("rect", -1)},
                                      {"rect", Tcl_NewListObj(4, rect)},
                                      {"slip", Tcl_NewBooleanObj(o.rect.slip)},
                                      {"nodes", Tcl_NewWideIntObj(Tcl_WideInt(o.nodes))},
                                      {"force", newVec2(o.force)},
                                      {"torque", newDouble(o.torque)}}));
    return TCL_OK;
  });
}

int LatticeObstacles(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc != 1) {
    Tcl_WrongNumArgs(interp, 1, objv, nullptr);
    return TCL_ERROR;
  }
  return guarded(interp, [&] {
    Tcl_Obj* ids = Tcl_NewListObj(0, nullptr);
    for (int id : sessionOf(data).manager.lattice().obstacleIds())
      Tcl_ListObjAppendElement(nullptr, ids, Tcl_NewIntObj(id));
    Tcl_SetObjResult(interp, ids);
    return TCL_OK;
  });
}

}  // namespace

void registerLatticeCommands(Tcl_Interp* interp, Session* session) {
  makeEnsemble(
      interp, "::sf::lattice",
      {{"create", LatticeCreate},
       {"configure", LatticeConfigure},
       {"cget", LatticeCget},
       {"info", LatticeInfo},
       {"probe", LatticeProbe},
       {"obstacle", nullptr},
       {"obstacles", LatticeObstacles},
       {"delete", LatticeDelete}},
      session,
      kOptions.answers("lattice",
                       {"create -size {Lx Ly} (-cells NX | -spacing h) ?-option value ...?",
                        "configure ?-option value ...?", "cget -option",
                        "info                    -> dict nx ny nodes spacing timestep tau ... "
                        "given",
                        "probe {x y}             -> dict density pressure velocity solid ...",
                        "obstacle rect {x0 y0 x1 y1} ?-slip 0|1? ?-id N?   -> id",
                        "obstacle circle {cx cy r} ?-outside 0|1? ?-velocity {vx vy w}? "
                        "?-id N?   -> id",
                        "obstacle delete ID", "obstacle info ID    -> dict ... force torque",
                        "obstacles               -> ids", "delete",
                        "options                 -> the options as dicts: name type unit "
                        "min max choices default help ...",
                        "help"},
                       defaults()));
  makeEnsemble(interp, "::sf::lattice::obstacle",
               {{"rect", ObstacleRect},
                {"circle", ObstacleCircle},
                {"delete", ObstacleDelete},
                {"info", ObstacleInfo}},
               session);
}

}  // namespace sf::tcl
