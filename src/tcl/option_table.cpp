// The parts of option tables that do not depend on what they configure.
#include "sandflow/tcl/option_table.hpp"

#include <cctype>
#include <cmath>

namespace sf::tcl {
namespace {

// "VALUE SUBSTEPS" from "-substeps".
std::string errorCodeOf(const char* name) {
  std::string code = "VALUE ";
  for (const char* c = name + 1; *c; ++c)
    code += char(std::toupper(static_cast<unsigned char>(*c)));
  return code;
}

// The range in words: "1 to 1000", "> 0", "> 0 and <= 2", ">= 0".
std::string rangeText(const Range& r, bool integer) {
  const bool lo = std::isfinite(r.min), hi = std::isfinite(r.max);
  if (integer && lo && hi && !r.minOpen && !r.maxOpen)
    return formatNumber(r.min) + " to " + formatNumber(r.max);
  std::string text;
  if (lo) text = (r.minOpen ? "> " : ">= ") + formatNumber(r.min);
  if (hi) text += std::string(lo ? " and " : "") + (r.maxOpen ? "< " : "<= ") + formatNumber(r.max);
  return text;
}

bool inRange(const Range& r, double v) {
  return (r.minOpen ? v > r.min : v >= r.min) && (r.maxOpen ? v < r.max : v <= r.max);
}

// A list of some of the choices: "bad WHAT "z": must be x, y, or rot" for one
// that is not.
bool getFlags(Tcl_Interp* interp, Tcl_Obj* obj, const OptionInfo& info, unsigned& flags) {
  int n = 0;
  Tcl_Obj** items = nullptr;
  if (Tcl_ListObjGetElements(interp, obj, &n, &items) != TCL_OK) return false;
  flags = 0;
  for (int i = 0; i < n; ++i) {
    int k = 0;
    if (!getChoice(interp, items[i], info.what ? info.what : info.name + 1, info.choices, k))
      return false;
    flags |= 1u << k;
  }
  return true;
}

}  // namespace

bool convertOption(Tcl_Interp* interp, Tcl_Obj* obj, const OptionInfo& info, OptionValue& out) {
  if (info.orEmpty) {
    int length = 0;
    Tcl_GetStringFromObj(obj, &length);
    if (length == 0) {
      out.empty = true;
      return true;
    }
  }
  double checked = 0;
  switch (info.kind) {
    case ValueKind::real:
      if (!getDouble(interp, obj, info.name, out.real)) return false;
      checked = out.real;
      break;
    case ValueKind::integer:
      if (!getInt(interp, obj, info.name, out.integer)) return false;
      checked = out.integer;
      break;
    case ValueKind::boolean:
      return getBool(interp, obj, info.name, out.boolean);
    case ValueKind::vec2:  // the range bounds each coordinate: check the first out of it
      if (!getVec2(interp, obj, info.name, out.vec)) return false;
      checked = inRange(info.range, out.vec.x()) ? out.vec.y() : out.vec.x();
      break;
    case ValueKind::vec3: {
      std::vector<double> v;
      if (!getDoubles(interp, obj, info.name, 3, v)) return false;
      out.vec3 = Eigen::Vector3d(v[0], v[1], v[2]);
      return true;
    }
    case ValueKind::flags:
      return getFlags(interp, obj, info, out.flags);
    case ValueKind::choice:
      return getChoice(interp, obj, info.what ? info.what : info.name + 1, info.choices,
                       out.choice);
    case ValueKind::custom:
      return true;  // the row converts it
  }
  if (inRange(info.range, checked)) return true;
  if (info.outOfRange) return reject(interp, errorCodeOf(info.name), info.outOfRange(checked));
  return reject(interp, errorCodeOf(info.name),
                std::string(info.name) + " must be " +
                    rangeText(info.range, info.kind == ValueKind::integer) + ", got " +
                    (info.kind == ValueKind::vec2 ? formatNumber(checked) : Tcl_GetString(obj)));
}

Tcl_Obj* optionObj(const OptionInfo& info, const OptionValue& value) {
  if (value.empty) return Tcl_NewObj();
  switch (info.kind) {
    case ValueKind::real:
      return std::isnan(value.real) ? Tcl_NewObj() : newDouble(value.real);
    case ValueKind::integer:
      return Tcl_NewIntObj(value.integer);
    case ValueKind::boolean:
      return Tcl_NewBooleanObj(value.boolean);
    case ValueKind::vec2:
      return newVec2(value.vec);
    case ValueKind::choice:
      return Tcl_NewStringObj(info.choices[value.choice], -1);
    case ValueKind::vec3: {
      Tcl_Obj* items[3] = {newDouble(value.vec3[0]), newDouble(value.vec3[1]),
                           newDouble(value.vec3[2])};
      return Tcl_NewListObj(3, items);
    }
    case ValueKind::flags: {
      Tcl_Obj* list = Tcl_NewListObj(0, nullptr);
      for (int k = 0; info.choices[k]; ++k)
        if (value.flags & (1u << k))
          Tcl_ListObjAppendElement(nullptr, list, Tcl_NewStringObj(info.choices[k], -1));
      return list;
    }
    case ValueKind::custom:
      break;
  }
  return Tcl_NewObj();
}

Tcl_Obj* describeOption(const OptionInfo& info, Tcl_Obj* defaultValue) {
  static const char* const kinds[] = {"real",   "integer", "boolean", "vec2",
                                      "choice", "custom",  "vec3",    "flags"};
  const Range& r = info.range;
  const bool numeric = info.kind == ValueKind::real || info.kind == ValueKind::integer ||
                       info.kind == ValueKind::vec2;
  Tcl_Obj* choices = Tcl_NewListObj(0, nullptr);
  for (const char* const* c = info.choices; c && *c; ++c)
    Tcl_ListObjAppendElement(nullptr, choices, Tcl_NewStringObj(*c, -1));
  return newDict(
      {{"name", Tcl_NewStringObj(info.name, -1)},
       {"synopsis", Tcl_NewStringObj(info.synopsis, -1)},
       {"help", Tcl_NewStringObj(info.help, -1)},
       {"type", Tcl_NewStringObj(kinds[int(info.kind)], -1)},
       {"unit", Tcl_NewStringObj(info.unit, -1)},
       {"min", numeric && std::isfinite(r.min) ? newDouble(r.min) : Tcl_NewObj()},
       {"max", numeric && std::isfinite(r.max) ? newDouble(r.max) : Tcl_NewObj()},
       {"minopen", Tcl_NewBooleanObj(r.minOpen)},
       {"maxopen", Tcl_NewBooleanObj(r.maxOpen)},
       {"choices", choices},
       {"default", info.defaultText ? Tcl_NewStringObj(info.defaultText, -1) : defaultValue}});
}

}  // namespace sf::tcl
