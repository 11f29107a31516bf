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
struct LatticeStage {
  LatticeDef def;
  int nx = 0;
  double h = 0, viscosity = 0, tau = 0;

  static LatticeStage of(const lb::ResolvedLattice& p) {
    LatticeStage s{p.def, p.nx, p.h, p.viscosity, p.tau};
    s.def.viscosity = p.viscosity, s.def.tau = p.tau, s.def.timestep = p.dt;
    s.def.cells = p.nx, s.def.spacing = 0;
    return s;
  }
};

using Row = Option<LatticeStage>;
// In this order: -periodic is applied before -walls.
const OptionTable<LatticeStage> kOptions{
    {Row{{"-origin", "{x0 y0}", "lower-left corner", ValueKind::vec2, "length"},
         [](const LatticeStage& s) { return vecValue(s.def.origin); },
         [](LatticeStage& s, const OptionValue& v) { s.def.origin = v.vec; }},
     Row{{"-size",
          "{Lx Ly}",
          "width and height, whole numbers of spacings",
          ValueKind::vec2,
          "length",
          {.min = 0, .minOpen = true},
          nullptr,
          nullptr,
          nullptr,
          ""},
         [](const LatticeStage& s) { return vecValue(s.def.size); },
         [](LatticeStage& s, const OptionValue& v) { s.def.size = v.vec; }},
     Row{{"-cells",
          "NX",
          "cells across x (or give -spacing)",
          ValueKind::integer,
          "",
          {.min = 1},
          nullptr,
          nullptr,
          nullptr,
          ""},
         [](const LatticeStage& s) { return integerValue(s.nx); },
         [](LatticeStage& s, const OptionValue& v) { s.def.cells = v.integer, s.def.spacing = 0; }},
     Row{{"-spacing",
          "h",
          "node spacing (or give -cells)",
          ValueKind::real,
          "length",
          {.min = 0, .minOpen = true},
          nullptr,
          nullptr,
          nullptr,
          ""},
         [](const LatticeStage& s) { return realValue(s.h); },
         [](LatticeStage& s, const OptionValue& v) { s.def.spacing = v.real, s.def.cells = 0; }},
     Row{{"-viscosity",
          "nu",
          "kinematic viscosity; with tau it sets the timestep",
          ValueKind::real,
          "length^2/time",
          {.min = 0, .minOpen = true},
          nullptr,
          nullptr,
          nullptr,
          ""},
         [](const LatticeStage& s) { return realValue(s.viscosity); },
         [](LatticeStage& s, const OptionValue& v) { s.def.viscosity = v.real; }},
     Row{{"-density",
          "rho0",
          "initial and reference density",
          ValueKind::real,
          "mass/length^2",
          {.min = 0, .minOpen = true}},
         [](const LatticeStage& s) { return realValue(s.def.density); },
         [](LatticeStage& s, const OptionValue& v) { s.def.density = v.real; }},
     Row{{"-tau",
          "tau",
          "relaxation time (a fixed sim -timestep sets it instead)",
          ValueKind::real,
          "",
          {.min = 0.5, .minOpen = true},
          nullptr,
          nullptr,
          [](double tau) { return "tau " + formatNumber(tau) + " is unstable: must exceed 0.5"; },
          "1"},
         [](const LatticeStage& s) { return realValue(s.tau); },
         [](LatticeStage& s, const OptionValue& v) { s.def.tau = v.real; }},
     Row{{"-periodic", "{x y}", "periodic axes: two booleans, or axis names", ValueKind::custom},
         nullptr,
         nullptr,
         [](Tcl_Interp* interp, Tcl_Obj* v, LatticeStage& s) {
           return parsePeriodic(interp, v, s.def);
         },
         [](const LatticeStage& s) {
           Tcl_Obj* flags[2] = {
               Tcl_NewBooleanObj(s.def.sides[lb::left].kind == SideKind::periodic),
               Tcl_NewBooleanObj(s.def.sides[lb::bottom].kind == SideKind::periodic)};
           return Tcl_NewListObj(2, flags);
         }},
     Row{{"-walls", "{side kind ...}",
          "sides left right bottom top: noslip ?{vx vy}?, slip, periodic, velocity {vx vy}, "
          "pressure p",
          ValueKind::custom},
         nullptr,
         nullptr,
         [](Tcl_Interp* interp, Tcl_Obj* v, LatticeStage& s) {
           return parseWalls(interp, v, s.def);
         },
         [](const LatticeStage& s) { return wallsValue(s.def); }},
     Row{{"-forcing", "{Fx Fy}", "body force per unit area (rho a)", ValueKind::vec2,
          "mass/(length time^2)"},
         [](const LatticeStage& s) { return vecValue(s.def.forcing); },
         [](LatticeStage& s, const OptionValue& v) { s.def.forcing = v.vec; }},
     Row{{"-collision",
          "bgk|trt",
          "collision operator",
          ValueKind::choice,
          "",
          {},
          kCollisionNames,
          "collision"},
         [](const LatticeStage& s) { return choiceValue(int(s.def.collision)); },
         [](LatticeStage& s, const OptionValue& v) { s.def.collision = lb::Collision(v.choice); }},
     Row{{"-forcescheme",
          "nodal|guo",
          "body-force scheme (nodal: the thesis's)",
          ValueKind::choice,
          "",
          {},
          kForceSchemeNames,
          "force scheme"},
         [](const LatticeStage& s) { return choiceValue(int(s.def.forceScheme)); },
         [](LatticeStage& s, const OptionValue& v) {
           s.def.forceScheme = lb::ForceScheme(v.choice);
         }},
     Row{{"-magic",
          "Lambda",
          "TRT magic parameter (0.1875: walls exactly halfway)",
          ValueKind::real,
          "",
          {.min = 0, .minOpen = true}},
         [](const LatticeStage& s) { return realValue(s.def.magic); },
         [](LatticeStage& s, const OptionValue& v) { s.def.magic = v.real; }}},
    true};
enum { kSize = 1, kCells, kSpacing, kViscosity, kDensity, kTau };

// A new lattice's settings, for help's and `lattice options`' defaults.
const LatticeStage& defaults() {
  static const LatticeStage d = [] {
    LatticeStage s;
    s.tau = 1;
    return s;
  }();
  return d;
}

int LatticeCreate(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  Session& s = sessionOf(data);
  if (objc < 2 || objc % 2 == 0) {
    Tcl_WrongNumArgs(interp, 1, objv, "-size {Lx Ly} (-cells NX | -spacing h) ?-option value ...?");
    return TCL_ERROR;
  }
  LatticeStage stage;
  std::vector<bool> given;
  if (!kOptions.apply(interp, objc, objv, 1, stage, &given)) return TCL_ERROR;
  const LatticeDef& def = stage.def;
  if (!given[kSize]) return fail(interp, "VALUE SIZE", "lattice create needs -size {Lx Ly}");
  if (given[kCells] == given[kSpacing])
    return fail(interp, "VALUE CELLS", "lattice create needs exactly one of -cells and -spacing");
  const int code = guarded(interp, [&] {
    s.manager.createLattice(def);
    return TCL_OK;
  });
  flushWarnings(s);  // told now (BGK at tau 3 along walls), not at the first step
  return code;
}

int LatticeConfigure(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  Session& s = sessionOf(data);
  const int code = guarded(interp, [&] {
    LatticeStage stage = LatticeStage::of(s.manager.lattice().params());
    if (objc == 1) {
      Tcl_SetObjResult(interp, kOptions.all(stage));
      return TCL_OK;
    }
    if (objc == 2) {  // like Tk: "configure -option" reports that option
      const int k = optionIndex(interp, objv[1], kOptions.specs());
      if (k < 0) return TCL_ERROR;
      Tcl_SetObjResult(interp, kOptions.get(stage, k));
      return TCL_OK;
    }
    if (objc % 2 == 0) {
      Tcl_WrongNumArgs(interp, 1, objv, "?-option value ...?");
      return TCL_ERROR;
    }
    std::vector<bool> given;
    if (!kOptions.apply(interp, objc, objv, 1, stage, &given)) return TCL_ERROR;
    LatticeDef& def = stage.def;  // (a new density: the kernel refuses it)
    // Keep the timestep unless tau is what changed. Neither given: the two
    // of viscosity, tau and timestep the lattice was given, not all three
    // resolved (which would give the timestep again to the last bit or not).
    const LatticeDef& was = s.manager.lattice().params().def;
    if (!given[kViscosity] && !given[kTau])
      def.viscosity = was.viscosity, def.tau = was.tau, def.timestep = was.timestep;
    if (given[kViscosity] && !given[kTau]) def.tau.reset();
    if (given[kTau]) def.timestep.reset();
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
    const LatticeStage stage = LatticeStage::of(s.manager.lattice().params());
    const int k = optionIndex(interp, objv[1], kOptions.specs());
    if (k < 0) return TCL_ERROR;
    Tcl_SetObjResult(interp, kOptions.get(stage, k));
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
                 {"bytespernode", newDouble(double(l.memoryBytes()) / double(l.nodes()))}}));
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

const OptionSpec kRectOptions[] = {
    {"-slip", "0|1", "specular (free-slip) walls instead of no-slip (default 0)"},
    {"-id", "N", "the obstacle's id (default: the next free one)"},
    {nullptr, nullptr, nullptr}};

int ObstacleRect(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  Session& s = sessionOf(data);
  if (objc < 2 || objc % 2 == 1) {
    Tcl_WrongNumArgs(interp, 1, objv, "{x0 y0 x1 y1} ?-slip 0|1? ?-id N?");
    return TCL_ERROR;
  }
  std::vector<double> box;
  if (!getDoubles(interp, objv[1], "rect", 4, box)) return TCL_ERROR;
  lb::RectObstacle r;
  r.id = -1;
  r.lo = Vec2(box[0], box[1]);
  r.hi = Vec2(box[2], box[3]);
  if (!parseOptions(interp, objc, objv, 2, kRectOptions, [&](int k, Tcl_Obj* v) {
        if (k == 0) return getBool(interp, v, "-slip", r.slip);
        if (!getInt(interp, v, "-id", r.id)) return false;
        if (r.id < 0)
          return reject(interp, "VALUE ID", "-id must be >= 0, got " + std::to_string(r.id));
        return true;
      }))
    return TCL_ERROR;
  return guarded(interp, [&] {
    Tcl_SetObjResult(interp, Tcl_NewIntObj(s.manager.lattice().addObstacle(r)));
    return TCL_OK;
  });
}

const OptionSpec kCircleOptions[] = {
    {"-outside", "0|1", "solid outside the circle instead of inside: a container (default 0)"},
    {"-velocity", "{vx vy w}", "translation and rotation rate of the wall (default {0 0 0})"},
    {"-id", "N", "the obstacle's id (default: the next free one)"},
    {nullptr, nullptr, nullptr}};

int ObstacleCircle(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  Session& s = sessionOf(data);
  if (objc < 2 || objc % 2 == 1) {
    Tcl_WrongNumArgs(interp, 1, objv, "{cx cy r} ?-outside 0|1? ?-velocity {vx vy w}? ?-id N?");
    return TCL_ERROR;
  }
  std::vector<double> circle;
  if (!getDoubles(interp, objv[1], "circle", 3, circle)) return TCL_ERROR;
  lb::CircleObstacle c;
  c.id = -1;
  c.centre = Vec2(circle[0], circle[1]);
  c.radius = circle[2];
  if (!(c.radius > 0))
    return fail(interp, "VALUE RADIUS", "circle radius must be > 0, got " + formatNumber(c.radius));
  if (!parseOptions(interp, objc, objv, 2, kCircleOptions, [&](int k, Tcl_Obj* v) {
        if (k == 0) return getBool(interp, v, "-outside", c.outside);
        if (k == 1) {
          std::vector<double> vel;
          if (!getDoubles(interp, v, "-velocity", 3, vel)) return false;
          c.velocity = Vec2(vel[0], vel[1]);
          c.spin = vel[2];
          return true;
        }
        if (!getInt(interp, v, "-id", c.id)) return false;
        if (c.id < 0)
          return reject(interp, "VALUE ID", "-id must be >= 0, got " + std::to_string(c.id));
        return true;
      }))
    return TCL_ERROR;
  return guarded(interp, [&] {
    Tcl_SetObjResult(interp, Tcl_NewIntObj(s.manager.lattice().addCircle(c)));
    return TCL_OK;
  });
}

bool getObstacleId(Tcl_Interp* interp, int objc, Tcl_Obj* const objv[], int& id) {
  if (objc != 2) {
    Tcl_WrongNumArgs(interp, 1, objv, "ID");
    return false;
  }
  return getInt(interp, objv[1], "ID", id);
}

int ObstacleDelete(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  int id = 0;
  if (!getObstacleId(interp, objc, objv, id)) return TCL_ERROR;
  return guarded(interp, [&] {
    sessionOf(data).manager.lattice().deleteObstacle(id);
    return TCL_OK;
  });
}

int ObstacleInfo(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  int id = 0;
  if (!getObstacleId(interp, objc, objv, id)) return TCL_ERROR;
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

// The option table, one dict per option (the workbench's property panel).
int LatticeOptions(ClientData, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc != 1) {
    Tcl_WrongNumArgs(interp, 1, objv, nullptr);
    return TCL_ERROR;
  }
  Tcl_SetObjResult(interp, kOptions.describe(defaults()));
  return TCL_OK;
}

int LatticeHelp(ClientData, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc != 1) {
    Tcl_WrongNumArgs(interp, 1, objv, nullptr);
    return TCL_ERROR;
  }
  Tcl_SetObjResult(interp,
                   newString(kOptions.help(
                       "lattice",
                       {"create -size {Lx Ly} (-cells NX | -spacing h) ?-option value ...?",
                        "configure ?-option value ...?", "cget -option",
                        "info                    -> dict nx ny nodes spacing timestep tau ...",
                        "probe {x y}             -> dict density pressure velocity solid ...",
                        "obstacle rect {x0 y0 x1 y1} ?-slip 0|1? ?-id N?   -> id",
                        "obstacle circle {cx cy r} ?-outside 0|1? ?-velocity {vx vy w}? "
                        "?-id N?   -> id",
                        "obstacle delete ID", "obstacle info ID    -> dict ... force torque",
                        "obstacles               -> ids", "delete",
                        "options                 -> the options as dicts: name type unit "
                        "min max choices default help ...",
                        "help"},
                       defaults())));
  return TCL_OK;
}

}  // namespace

void registerLatticeCommands(Tcl_Interp* interp, Session* session) {
  makeEnsemble(interp, "::sf::lattice",
               {{"create", LatticeCreate},
                {"configure", LatticeConfigure},
                {"cget", LatticeCget},
                {"info", LatticeInfo},
                {"probe", LatticeProbe},
                {"obstacle", nullptr},
                {"obstacles", LatticeObstacles},
                {"delete", LatticeDelete},
                {"options", LatticeOptions},
                {"help", LatticeHelp}},
               session);
  makeEnsemble(interp, "::sf::lattice::obstacle",
               {{"rect", ObstacleRect},
                {"circle", ObstacleCircle},
                {"delete", ObstacleDelete},
                {"info", ObstacleInfo}},
               session);
}

}  // namespace sf::tcl
