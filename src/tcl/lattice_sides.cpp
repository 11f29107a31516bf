// -walls and -periodic: a lattice's sides read from and shown as Tcl values.
#include "lattice_sides.hpp"

#include <cctype>
#include <cmath>
#include <iterator>

#include "sandflow/core/error.hpp"
#include "sandflow/tcl/args.hpp"

namespace sf::tcl {
namespace {

using lb::LatticeDef;
using lb::SideKind;

const char* const kSideNames[] = {"left", "right", "bottom", "top", nullptr};
const char* const kKindNames[] = {"periodic", "noslip",  "slip", "velocity",
                                  "pressure", "outflow", nullptr};
const char* const kProfileNames[] = {"uniform", "parabolic", nullptr};
const char* const kVelocityOptions[] = {"-profile", "-ramp", "-expr", nullptr};
const char* const kUsage[] = {
    "periodic",
    "noslip ?{vx vy}?",
    "slip",
    "velocity {vx vy} ?-profile uniform|parabolic? ?-ramp T? or velocity -expr {EXPR_X EXPR_Y} "
    "?-ramp T?",
    "pressure p",
    "outflow"};

bool badSpec(Tcl_Interp* interp, Tcl_Obj* spec, int kind) {
  return reject(interp, "VALUE WALLS",
                std::string("wall \"") + Tcl_GetString(spec) + "\" must be " + kUsage[kind]);
}

// Whether an expression reads the variable `name` ($t or ${t}).
bool readsVariable(const std::string& text, char name) {
  for (std::size_t at = text.find('$'); at != std::string::npos; at = text.find('$', at + 1)) {
    const std::string rest = text.substr(at + 1, 3);
    if (rest.rfind(std::string("{") + name + "}", 0) == 0) return true;
    if (rest.empty() || rest[0] != name) continue;
    const char next = rest.size() > 1 ? rest[1] : ' ';
    if (!std::isalnum(static_cast<unsigned char>(next)) && next != '_' && next != ':' &&
        next != '(')
      return true;
  }
  return false;
}

// velocity {vx vy} ?-profile P? ?-ramp T?, or velocity -expr {EX EY} ?-ramp T?
bool parseVelocity(Tcl_Interp* interp, Tcl_Obj* spec, int n, Tcl_Obj** words, lb::SideDef& side) {
  int at = 1;
  bool given = false, profileGiven = false;
  if (at < n && Tcl_GetString(words[at])[0] != '-') {
    if (!getVec2(interp, words[at], "-walls", side.velocity)) return false;
    given = true, ++at;
  }
  if ((n - at) % 2) return badSpec(interp, spec, int(SideKind::velocity));
  for (; at < n; at += 2) {
    int option = 0;
    if (!getChoice(interp, words[at], "velocity side option", kVelocityOptions, option))
      return false;
    Tcl_Obj* value = words[at + 1];
    if (option == 0) {
      int profile = 0;
      if (!getChoice(interp, value, "profile", kProfileNames, profile)) return false;
      side.profile = lb::SideProfile(profile), profileGiven = true;
    } else if (option == 1) {
      if (!getDouble(interp, value, "-ramp", side.ramp)) return false;
      if (!(side.ramp >= 0) || !std::isfinite(side.ramp))
        return reject(interp, "VALUE WALLS",
                      "-ramp must be a time >= 0, got " + std::string(Tcl_GetString(value)));
    } else {
      int count = 0;
      Tcl_Obj** texts = nullptr;
      if (Tcl_ListObjGetElements(interp, value, &count, &texts) != TCL_OK) return false;
      if (count != 2 || !*Tcl_GetString(texts[0]) || !*Tcl_GetString(texts[1]))
        return reject(interp, "VALUE WALLS",
                      std::string("-expr must be two expressions {EXPR_X EXPR_Y}, got \"") +
                          Tcl_GetString(value) + "\"");
      side.expr = {Tcl_GetString(texts[0]), Tcl_GetString(texts[1])};
      side.timed = readsVariable(side.expr[0], 't') || readsVariable(side.expr[1], 't');
    }
  }
  if (side.byExpression() && (given || profileGiven))
    return reject(interp, "VALUE WALLS",
                  std::string("wall \"") + Tcl_GetString(spec) +
                      "\": -expr gives the whole profile: no {vx vy} nor -profile beside it");
  if (!side.byExpression() && !given) return badSpec(interp, spec, int(SideKind::velocity));
  return true;
}

bool parseWallSpec(Tcl_Interp* interp, Tcl_Obj* spec, lb::SideDef& side) {
  int n = 0;
  Tcl_Obj** words = nullptr;
  if (Tcl_ListObjGetElements(interp, spec, &n, &words) != TCL_OK) return false;
  int kind = 0;
  if (n == 0) return reject(interp, "VALUE WALLS", "empty wall kind in -walls");
  if (!getChoice(interp, words[0], "wall kind", kKindNames, kind)) return false;
  side = lb::SideDef{static_cast<SideKind>(kind)};
  if (kind == int(SideKind::velocity)) return parseVelocity(interp, spec, n, words, side);
  const bool ok =
      n == (kind == int(SideKind::pressure) ? 2 : 1) || (kind == int(SideKind::noslip) && n == 2);
  if (!ok) return badSpec(interp, spec, kind);
  if (kind == int(SideKind::pressure)) return getDouble(interp, words[1], "-walls", side.pressure);
  if (n == 2) return getVec2(interp, words[1], "-walls", side.velocity);
  return true;
}

// The apply lambda that evaluates a side's two expressions at every node: in
// the global namespace, with $s, $t and $L set and nothing else of the caller's.
Tcl_Obj* evaluator() {
  return Tcl_NewStringObj(
      "{t L __sf_nodes __sf_ex __sf_ey} {"
      "set __sf_r {}; foreach s $__sf_nodes {lappend __sf_r [expr $__sf_ex] [expr $__sf_ey]};"
      "return $__sf_r} ::",
      -1);
}

std::string sideExprText(int side, const lb::SideDef& d) {
  Tcl_Obj* texts[2] = {newString(d.expr[0]), newString(d.expr[1])};
  Tcl_Obj* list = Tcl_NewListObj(2, texts);  // as -walls takes it
  Tcl_IncrRefCount(list);
  const std::string text =
      std::string(kSideNames[side]) + " side's -expr {" + Tcl_GetString(list) + "}";
  Tcl_DecrRefCount(list);
  return text;
}

// The side's expressions at its nodes at time t (physical units). Throws
// sf::Error "VALUE WALLS" with Tcl's message or the value that is no number.
std::vector<Vec2> evaluateSide(Tcl_Interp* interp, const lb::ResolvedLattice& r, int side,
                               double t) {
  const lb::SideDef& d = r.def.sides[side];
  const int n = lb::sideNodeCount(r, side);
  Tcl_Obj* nodes = Tcl_NewListObj(0, nullptr);
  for (int k = 0; k < n; ++k)
    Tcl_ListObjAppendElement(nullptr, nodes, Tcl_NewDoubleObj(lb::sideNodeDistance(r, k)));
  Tcl_Obj* words[] = {Tcl_NewStringObj("::apply", -1),
                      evaluator(),
                      Tcl_NewDoubleObj(t),
                      Tcl_NewDoubleObj(lb::sideLength(r, side)),
                      nodes,
                      Tcl_NewStringObj(d.expr[0].c_str(), -1),
                      Tcl_NewStringObj(d.expr[1].c_str(), -1)};
  for (Tcl_Obj* w : words) Tcl_IncrRefCount(w);
  const int code = Tcl_EvalObjv(interp, int(std::size(words)), words, TCL_EVAL_GLOBAL);
  for (Tcl_Obj* w : words) Tcl_DecrRefCount(w);
  const std::string where = sideExprText(side, d) + " at t = " + formatNumber(t);
  if (code != TCL_OK) throw Error("VALUE WALLS", where + ": " + Tcl_GetStringResult(interp));
  Tcl_Obj* result = Tcl_GetObjResult(interp);
  Tcl_IncrRefCount(result);
  Tcl_ResetResult(interp);
  int count = 0;
  Tcl_Obj** items = nullptr;
  std::vector<Vec2> values(n);
  std::string bad;
  if (Tcl_ListObjGetElements(nullptr, result, &count, &items) != TCL_OK || count != 2 * n)
    bad = "does not give two numbers a node";
  for (int k = 0; k < n && bad.empty(); ++k)
    for (int c = 0; c < 2 && bad.empty(); ++c) {
      double v = 0;
      if (Tcl_GetDoubleFromObj(nullptr, items[2 * k + c], &v) != TCL_OK)
        bad = std::string("gives \"") + Tcl_GetString(items[2 * k + c]) +
              "\", not a number, at s = " + formatNumber(lb::sideNodeDistance(r, k));
      values[k][c] = v;
    }
  Tcl_DecrRefCount(result);
  if (!bad.empty()) throw Error("VALUE WALLS", where + " " + bad);
  return values;
}

}  // namespace

void evaluateSideExpressions(Tcl_Interp* interp, LatticeDef& def, double t) {
  bool any = false;
  LatticeDef geometry = def;  // sides without values yet: resolved for the grid alone
  for (lb::SideDef& side : geometry.sides)
    if (side.byExpression()) side = lb::SideDef{SideKind::velocity}, any = true;
  if (!any) return;
  const lb::ResolvedLattice r = lb::resolve(geometry);
  std::array<std::vector<Vec2>, 4> values;
  for (int s = 0; s < 4; ++s) {
    if (!def.sides[s].byExpression()) continue;
    lb::ResolvedLattice at = r;
    at.def.sides[s] = def.sides[s];
    values[s] = evaluateSide(interp, at, s, t);
  }
  for (int s = 0; s < 4; ++s)
    if (def.sides[s].byExpression()) def.sides[s].values = std::move(values[s]);
}

void updateTimedSides(Tcl_Interp* interp, sim::Manager& manager) {
  if (!manager.hasLattice()) return;
  lb::Lattice& lattice = manager.lattice();
  const double t = manager.time() + lattice.params().dt;
  for (int s = 0; s < 4; ++s)
    if (lattice.params().def.sides[s].timed)
      lattice.setSideValues(s, evaluateSide(interp, lattice.params(), s, t));
}

bool parseWalls(Tcl_Interp* interp, Tcl_Obj* value, LatticeDef& def) {
  int n = 0;
  Tcl_Obj** items = nullptr;
  if (Tcl_ListObjGetElements(interp, value, &n, &items) != TCL_OK) return false;
  if (n % 2)
    return fail(interp, "VALUE WALLS",
                "-walls must be a list of side and kind pairs, e.g. {bottom noslip top slip}") ==
           TCL_OK;
  for (int i = 0; i < n; i += 2) {
    int side = 0;
    if (!getChoice(interp, items[i], "side", kSideNames, side)) return false;
    if (!parseWallSpec(interp, items[i + 1], def.sides[side])) return false;
    if (def.sides[side].kind == SideKind::periodic) def.sides[side ^ 1] = def.sides[side];
  }
  return true;
}

bool parsePeriodic(Tcl_Interp* interp, Tcl_Obj* value, LatticeDef& def) {
  int n = 0;
  Tcl_Obj** items = nullptr;
  if (Tcl_ListObjGetElements(interp, value, &n, &items) != TCL_OK) return false;
  bool flags[2] = {false, false};
  int b0 = 0, b1 = 0;
  if (n == 2 && Tcl_GetBooleanFromObj(nullptr, items[0], &b0) == TCL_OK &&
      Tcl_GetBooleanFromObj(nullptr, items[1], &b1) == TCL_OK) {
    flags[0] = b0, flags[1] = b1;
  } else {
    static const char* const axes[] = {"x", "y", nullptr};
    for (int i = 0; i < n; ++i) {
      int axis = 0;
      if (!getChoice(interp, items[i], "periodic axis", axes, axis)) return false;
      flags[axis] = true;
    }
  }
  for (int axis = 0; axis < 2; ++axis)
    for (int side : {2 * axis, 2 * axis + 1}) {
      if (flags[axis])
        def.sides[side] = lb::SideDef{SideKind::periodic};
      else if (def.sides[side].kind == SideKind::periodic)
        def.sides[side] = lb::SideDef{};
    }
  return true;
}

Tcl_Obj* wallsValue(const LatticeDef& def) {
  Tcl_Obj* d = Tcl_NewDictObj();
  for (int s = 0; s < 4; ++s) {
    const lb::SideDef& side = def.sides[s];
    Tcl_Obj* spec = Tcl_NewListObj(0, nullptr);
    Tcl_ListObjAppendElement(nullptr, spec, Tcl_NewStringObj(kKindNames[int(side.kind)], -1));
    if (side.kind == SideKind::velocity && side.byExpression()) {
      Tcl_Obj* texts[2] = {newString(side.expr[0]), newString(side.expr[1])};
      Tcl_ListObjAppendElement(nullptr, spec, Tcl_NewStringObj("-expr", -1));
      Tcl_ListObjAppendElement(nullptr, spec, Tcl_NewListObj(2, texts));
    } else if (side.kind == SideKind::velocity ||
               (side.kind == SideKind::noslip && !side.velocity.isZero())) {
      Tcl_ListObjAppendElement(nullptr, spec, newVec2(side.velocity));
    }
    if (side.kind == SideKind::velocity && side.profile != lb::SideProfile::uniform) {
      Tcl_ListObjAppendElement(nullptr, spec, Tcl_NewStringObj("-profile", -1));
      Tcl_ListObjAppendElement(nullptr, spec,
                               Tcl_NewStringObj(kProfileNames[int(side.profile)], -1));
    }
    if (side.kind == SideKind::velocity && side.ramp > 0) {
      Tcl_ListObjAppendElement(nullptr, spec, Tcl_NewStringObj("-ramp", -1));
      Tcl_ListObjAppendElement(nullptr, spec, newDouble(side.ramp));
    }
    if (side.kind == SideKind::pressure)
      Tcl_ListObjAppendElement(nullptr, spec, newDouble(side.pressure));
    dictPut(d, kSideNames[s], spec);
  }
  return d;
}

}  // namespace sf::tcl
