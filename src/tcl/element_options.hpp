#pragma once
// The element commands' options as one table of rows (option_table.hpp): each
// creator takes a subset, `element configure` another, and `element options`
// describes configure's.
#include <tcl.h>

#include <cstdint>
#include <optional>
#include <vector>

#include "sandflow/dem/assembly.hpp"
#include "sandflow/tcl/option_table.hpp"

namespace sf::tcl {

struct Session;

// An element's settings as options give them, each only when given (an edit)
// or when it applies to the shape (what configure shows).
struct ElementDraft {
  const dem::MaterialTable* materials = nullptr;  // where -material's names are
  std::optional<Vec2> center, from, to, acceleration, axes, exponents;
  std::optional<double> radius, length, thickness, angle;
  std::optional<double> stress;  // NaN: no servo
  std::optional<int> material, id, sides;
  std::optional<Eigen::Vector3d> velocity, force;
  std::optional<std::uint8_t> hold;
  std::optional<std::vector<Vec2>> vertices;

  // What `element configure ID` shows for the element in `slot`.
  static ElementDraft of(const dem::Assembly& a, int slot);
  // A new element's settings, for help and `element options`; a wall is held.
  static ElementDraft defaults(dem::ShapeType shape);
};

using ElementTable = OptionTable<ElementDraft>;
const ElementTable& discOptions();
const ElementTable& wallOptions();
const ElementTable& polygonOptions();
const ElementTable& ellipseOptions();
const ElementTable& superquadricOptions();
const ElementTable& configureOptions();

// `element options ?ID?`: configure's rows (only those that apply to `shape`
// where one is given), -material's choices the session's materials.
Tcl_Obj* describeConfigureOptions(const dem::MaterialTable& materials,
                                  std::optional<dem::ShapeType> shape);

// disc, wall, polygon, ellipse, superquadric: create and help (element_create.cpp).
void registerShapeCommands(Tcl_Interp* interp, Session* session);

}  // namespace sf::tcl
