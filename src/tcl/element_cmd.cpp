// element configure|cget|info|ids|delete|next|options|help
#include <algorithm>
#include <optional>

#include "element_options.hpp"
#include "sandflow/dem/polygon.hpp"
#include "sandflow/dem/superquadric.hpp"
#include "sandflow/tcl/args.hpp"
#include "sandflow/tcl/session.hpp"

namespace sf::tcl {
namespace {

using dem::ShapeType;

bool getElement(Tcl_Interp* interp, Tcl_Obj* obj, const dem::Assembly& a, int& slot) {
  int id = 0;
  if (!getInt(interp, obj, "ID", id)) return false;
  slot = a.bodies().slot(id);
  if (slot < 0) return reject(interp, "LOOKUP ELEMENT", "no element with id " + std::to_string(id));
  return true;
}

// The option of the part of an edit that the kernel refused, for errorInfo.
const char* optionOf(dem::EditPart part) {
  switch (part) {
    case dem::EditPart::from:
      return "-from";
    case dem::EditPart::to:
      return "-to";
    case dem::EditPart::radius:
      return "-radius";
    case dem::EditPart::material:
      return "-material";
    default:
      return "-stress";
  }
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
  const ElementTable& table = configureOptions();
  if (objc == 2) {
    Tcl_SetObjResult(interp, table.all(ElementDraft::of(a, slot)));
    return TCL_OK;
  }
  if (objc == 3) {
    const int k = optionIndex(interp, objv[2], table.specs());
    if (k < 0) return TCL_ERROR;
    Tcl_SetObjResult(interp, table.get(ElementDraft::of(a, slot), k));
    return TCL_OK;
  }
  if (objc % 2) {
    Tcl_WrongNumArgs(interp, 1, objv, "ID ?-option value ...?");
    return TCL_ERROR;
  }
  // Only the options given are staged; the kernel checks the edit whole
  // (what applies to the shape, the mass) before it changes anything.
  ElementDraft e;
  e.materials = &a.materials();
  if (!table.apply(interp, objc, objv, 2, e)) return TCL_ERROR;
  dem::ElementEdit edit;
  edit.center = e.center, edit.angle = e.angle, edit.from = e.from, edit.to = e.to;
  edit.radius = e.radius, edit.material = e.material, edit.velocity = e.velocity;
  edit.force = e.force, edit.acceleration = e.acceleration, edit.hold = e.hold;
  edit.stress = e.stress;
  try {
    a.configure(a.bodies().id[slot], edit);
  } catch (const dem::EditRefused& refused) {
    fail(interp, refused);
    noteOptionOnce(interp, optionOf(refused.part()));
    return TCL_ERROR;
  } catch (const Error& error) {
    fail(interp, error);
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
  const ElementTable& table = configureOptions();
  const int k = optionIndex(interp, objv[2], table.specs());
  if (k < 0) return TCL_ERROR;
  Tcl_SetObjResult(interp, table.get(ElementDraft::of(a, slot), k));
  return TCL_OK;
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
  const ElementDraft draft = ElementDraft::of(a, s);
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
                        {"material", newString(a.materials()[b.material[s]].name)},
                        {"fix", holdValue(b.hold[s])},
                        {"applied", triple(b.appliedForce[s], b.appliedTorque[s])},
                        {"acceleration", newVec2(b.acceleration[s])},
                        {"contacts", Tcl_NewIntObj(contacts)},
                        {"contactforce", newVec2(a.contactForce(s))},
                        {"fluidforce", newVec2(b.fluidForce[s])},
                        {"fluidtorque", newDouble(b.fluidTorque[s])},
                        {"buoyancy", newVec2(b.buoyancy[s])}});
  if (shape.type() == ShapeType::disc) dictPut(d, "radius", newDouble(*draft.radius));
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
    dictPut(d, "from", newVec2(*draft.from));
    dictPut(d, "to", newVec2(*draft.to));
    dictPut(d, "length", newDouble(static_cast<const dem::Wall&>(shape).length()));
    dictPut(d, "thickness", newDouble(*draft.thickness));
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

// configure's option table, one dict per option (the workbench's property
// panel builds its fields from it); -material's choices are the materials.
// With an ID, only the options that apply to that element's shape.
int ElementOptions(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  const dem::Assembly& a = sessionOf(data).manager.assembly();
  if (objc != 1 && objc != 2) {
    Tcl_WrongNumArgs(interp, 1, objv, "?ID?");
    return TCL_ERROR;
  }
  std::optional<ShapeType> shape;
  if (objc == 2) {
    int slot = 0;
    if (!getElement(interp, objv[1], a, slot)) return TCL_ERROR;
    shape = a.bodies().shape[slot]->type();
  }
  Tcl_SetObjResult(interp, describeConfigureOptions(a.materials(), shape));
  return TCL_OK;
}

}  // namespace

void registerElementCommands(Tcl_Interp* interp, Session* session) {
  registerShapeCommands(interp, session);
  makeEnsemble(
      interp, "::sf::element",
      {{"configure", ElementConfigure},
       {"cget", ElementCget},
       {"info", ElementInfo},
       {"ids", ElementIds},
       {"delete", ElementDelete},
       {"next", ElementNext},
       {"options", ElementOptions}},
      session,
      configureOptions().answers(
          "element",
          {"configure ID ?-option value ...?", "cget ID -option",
           "info ID   -> dict type position angle velocity force torque mass inertia ...",
           "ids ?-type disc|polygon|superquadric|wall?", "delete ID",
           "next      -> the next free id",
           "options ?ID?   -> configure's options (those that apply to element ID) as dicts: "
           "name type unit min max choices default ...",
           "help"},
          ElementDraft::defaults(ShapeType::disc), false));
}

}  // namespace sf::tcl
