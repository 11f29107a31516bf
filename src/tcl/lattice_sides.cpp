// -walls and -periodic: a lattice's sides read from and shown as Tcl values.
#include "lattice_sides.hpp"

#include "sandflow/tcl/args.hpp"

namespace sf::tcl {
namespace {

using lb::LatticeDef;
using lb::SideKind;

const char* const kSideNames[] = {"left", "right", "bottom", "top", nullptr};
const char* const kKindNames[] = {"periodic", "noslip", "slip", "velocity", "pressure", nullptr};

bool parseWallSpec(Tcl_Interp* interp, Tcl_Obj* spec, lb::SideDef& side) {
  int n = 0;
  Tcl_Obj** words = nullptr;
  if (Tcl_ListObjGetElements(interp, spec, &n, &words) != TCL_OK) return false;
  int kind = 0;
  if (n == 0) return reject(interp, "VALUE WALLS", "empty wall kind in -walls");
  if (!getChoice(interp, words[0], "wall kind", kKindNames, kind)) return false;
  side = lb::SideDef{static_cast<SideKind>(kind)};
  const char* usage[] = {"periodic", "noslip ?{vx vy}?", "slip", "velocity {vx vy}", "pressure p"};
  const int wanted = (kind == int(SideKind::velocity) || kind == int(SideKind::pressure)) ? 2 : 1;
  const bool ok = n == wanted || (kind == int(SideKind::noslip) && n == 2);
  if (!ok)
    return fail(interp, "VALUE WALLS",
                std::string("wall \"") + Tcl_GetString(spec) + "\" must be " + usage[kind]) ==
           TCL_OK;
  if (kind == int(SideKind::pressure)) return getDouble(interp, words[1], "-walls", side.pressure);
  if (n == 2) return getVec2(interp, words[1], "-walls", side.velocity);
  return true;
}

}  // namespace

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
    if (side.kind == SideKind::velocity ||
        (side.kind == SideKind::noslip && !side.velocity.isZero()))
      Tcl_ListObjAppendElement(nullptr, spec, newVec2(side.velocity));
    if (side.kind == SideKind::pressure)
      Tcl_ListObjAppendElement(nullptr, spec, newDouble(side.pressure));
    dictPut(d, kSideNames[s], spec);
  }
  return d;
}

}  // namespace sf::tcl
