#pragma once
// Option tables: each option of a configurable noun is one row -- name, value
// kind, unit, range, choices, help, and how it reads and writes the noun's
// draft of its settings (applied whole or not at all). configure, cget, help, `NOUN options` (which
// the workbench's property panel and the documentation read) all come from the rows, so an option's
// range is written once.
#include <functional>
#include <initializer_list>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "sandflow/core/assert.hpp"
#include "sandflow/tcl/args.hpp"

namespace sf::tcl {

// `custom`: the row converts and shows the value itself (a dict of walls, say).
// `flags`: a list of some of the choices, each at most once ({x rot}), shown in
// the choices' order.
enum class ValueKind { real, integer, boolean, vec2, choice, custom, vec3, flags };

// An interval; an end at infinity is not checked, an open end excludes itself.
// A vec2's range bounds each of its coordinates.
struct Range {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool minOpen = false, maxOpen = false;
};

// A value as converted from Tcl, in the member its kind uses.
struct OptionValue {
  double real = 0;
  int integer = 0;
  bool boolean = false;
  Vec2 vec = Vec2::Zero();
  int choice = 0;
  Eigen::Vector3d vec3 = Eigen::Vector3d::Zero();
  unsigned flags = 0;  // bit k: choices[k] is in the list
  bool empty = false;  // {} given where the row allows it (OptionInfo::orEmpty)
};

// A value of each kind, for the rows' getters.
inline OptionValue realValue(double v) {
  return {.real = v};
}
inline OptionValue integerValue(int v) {
  return {.integer = v};
}
inline OptionValue booleanValue(bool v) {
  return {.boolean = v};
}
inline OptionValue vecValue(const Vec2& v) {
  return {.vec = v};
}
inline OptionValue choiceValue(int v) {
  return {.choice = v};
}
inline OptionValue vec3Value(const Eigen::Vector3d& v) {
  return {.vec3 = v};
}
inline OptionValue flagsValue(unsigned v) {
  return {.flags = v};
}
// No value: the option does not apply (a wall's -radius), shown as {}.
inline OptionValue emptyValue() {
  return {.empty = true};
}

// What a row says about its option, whatever it configures.
struct OptionInfo {
  const char* name;      // "-timestep"
  const char* synopsis;  // the value's form in help: "dt"
  const char* help;      // one line, without the default (help adds it)
  ValueKind kind = ValueKind::real;
  const char* unit = "";  // in the user's consistent units, e.g. "time"
  Range range{};
  const char* const* choices = nullptr;  // ValueKind::choice, flags: null-terminated
  const char* what = nullptr;            // a choice's noun in "bad WHAT": default the name
  // The refusal of a value out of range, where it has its own words
  // ("tau 0.49 is unstable: must exceed 0.5"); default "-name must be ...".
  std::string (*outOfRange)(double value) = nullptr;
  const char* defaultText = nullptr;  // shown instead of the default read ("" : none)
  bool orEmpty = false;               // {} is a value too: "automatic" (a view's -field)
};

// Converts and checks a value for the option: false with the Tcl error set
// (Tcl's own message for a malformed value; "-name must be > 0, got -1" with
// errorCode SANDFLOW VALUE NAME for one out of range).
bool convertOption(Tcl_Interp* interp, Tcl_Obj* obj, const OptionInfo& info, OptionValue& out);
Tcl_Obj* optionObj(const OptionInfo& info, const OptionValue& value);
// The row as a dict: name synopsis help type unit min max minopen maxopen
// choices default (empty where it does not apply).
Tcl_Obj* describeOption(const OptionInfo& info, Tcl_Obj* defaultValue);

template <class Draft>
struct Option {
  OptionInfo info;
  std::function<OptionValue(const Draft&)> get = nullptr;
  std::function<void(Draft&, const OptionValue&)> set = nullptr;
  // Instead of get and set (ValueKind::custom, or a row whose choices are not
  // fixed): convert onto the draft (false with the error set), and show.
  std::function<bool(Tcl_Interp*, Tcl_Obj*, Draft&)> parse = nullptr;
  std::function<Tcl_Obj*(const Draft&)> show = nullptr;
};

// A row over a plain member of the draft: a real (double), a whole number
// (int), a boolean, or a text (std::string; std::optional<std::string>, shown
// as {} until given).
template <class Draft, class Value>
Option<Draft> memberRow(OptionInfo info, Value Draft::*member) {
  constexpr bool text =
      std::is_same_v<Value, std::string> || std::is_same_v<Value, std::optional<std::string>>;
  static_assert(text || std::is_same_v<Value, double> || std::is_same_v<Value, bool> ||
                std::is_same_v<Value, int>);
  if constexpr (text) {
    info.kind = ValueKind::custom;
    return {.info = info,
            .parse =
                [member](Tcl_Interp*, Tcl_Obj* v, Draft& d) {
                  d.*member = Tcl_GetString(v);
                  return true;
                },
            .show =
                [member](const Draft& d) {
                  if constexpr (std::is_same_v<Value, std::string>)
                    return Tcl_NewStringObj((d.*member).c_str(), -1);
                  else
                    return d.*member ? Tcl_NewStringObj((d.*member)->c_str(), -1) : Tcl_NewObj();
                }};
  } else {
    if constexpr (std::is_same_v<Value, bool>) info.kind = ValueKind::boolean;
    if constexpr (std::is_same_v<Value, int>) info.kind = ValueKind::integer;
    return {.info = info,
            .get =
                [member](const Draft& d) {
                  if constexpr (std::is_same_v<Value, bool>)
                    return booleanValue(d.*member);
                  else if constexpr (std::is_same_v<Value, int>)
                    return integerValue(d.*member);
                  else
                    return realValue(d.*member);
                },
            .set =
                [member](Draft& d, const OptionValue& v) {
                  if constexpr (std::is_same_v<Value, bool>)
                    d.*member = v.boolean;
                  else if constexpr (std::is_same_v<Value, int>)
                    d.*member = v.integer;
                  else
                    d.*member = v.real;
                }};
  }
}

// A row that converts its value itself and shows none ({} or, in help, the
// info's defaultText): a list of ids, a -series, columns.
template <class Draft>
Option<Draft> parsedRow(OptionInfo info, std::function<bool(Tcl_Interp*, Tcl_Obj*, Draft&)> parse) {
  info.kind = ValueKind::custom;
  return {
      .info = info, .parse = std::move(parse), .show = [](const Draft&) { return Tcl_NewObj(); }};
}

// -every K, a whole number >= 1: how often a run records or calls back.
template <class Draft>
Option<Draft> everyRow(const char* help, int Draft::*member, const char* defaultText = nullptr) {
  return memberRow(OptionInfo{.name = "-every",
                              .synopsis = "K",
                              .help = help,
                              .kind = ValueKind::integer,
                              .range = {.min = 1},
                              .defaultText = defaultText},
                   member);
}

// The rows of one noun. Keep it static: Tcl caches the name table by address.
template <class Draft>
class OptionTable {
 public:
  // inTableOrder: apply converts the options in the rows' order, not the
  // command's (a lattice's -periodic before its -walls).
  explicit OptionTable(std::initializer_list<Option<Draft>> rows, bool inTableOrder = false)
      : rows_(rows), inTableOrder_(inTableOrder) {
    for (const Option<Draft>& r : rows_)
      specs_.push_back({r.info.name, r.info.synopsis, r.info.help});
    specs_.push_back({nullptr, nullptr, nullptr});
  }
  int size() const { return int(rows_.size()); }
  // The row of option `name` ("-timestep"), for reading `given` by name
  // rather than by a count of rows kept in step by hand. A name no row has
  // is a bug in sandflow.
  int index(std::string_view name) const {
    const int k = find(name);
    SF_ASSERT(k >= 0 && "an option table has no row of that name");
    return k;
  }
  // The row of option `name`, or -1 where the table has none (a word of
  // another table, as output movie's view options).
  int find(std::string_view name) const {
    for (int k = 0; k < size(); ++k)
      if (name == info(k).name) return k;
    return -1;
  }
  const OptionInfo& info(int k) const { return rows_[std::size_t(k)].info; }
  // The plain rows, for parseOptions, optionIndex and helpText.
  const OptionSpec* specs() const { return specs_.data(); }

  // Reads "-option value" pairs from objv[first..) onto the draft; `given`
  // marks the options that came. False with the Tcl error set (and errorInfo
  // naming the option) on the first bad one; the draft is then half written.
  bool apply(Tcl_Interp* interp, int objc, Tcl_Obj* const objv[], int first, Draft& draft,
             std::vector<bool>* given = nullptr) const {
    if (given) given->assign(rows_.size(), false);
    std::vector<Tcl_Obj*> values(rows_.size(), nullptr);
    auto convert = [&](int k, Tcl_Obj* v) {
      const Option<Draft>& row = rows_[std::size_t(k)];
      if (given) (*given)[std::size_t(k)] = true;
      if (row.parse) return row.parse(interp, v, draft);
      OptionValue value;
      if (!convertOption(interp, v, info(k), value)) return false;
      row.set(draft, value);
      return true;
    };
    if (!parseOptions(interp, objc, objv, first, specs(), [&](int k, Tcl_Obj* v) {
          if (!inTableOrder_) return convert(k, v);
          values[std::size_t(k)] = v;  // the last of a repeated option wins
          return true;
        }))
      return false;
    for (int k = 0; k < size(); ++k)
      if (values[std::size_t(k)] && !convert(k, values[std::size_t(k)])) {
        noteOptionOnce(interp, info(k).name);
        return false;
      }
    return true;
  }
  Tcl_Obj* get(const Draft& draft, int k) const {
    const Option<Draft>& row = rows_[std::size_t(k)];
    return row.show ? row.show(draft) : optionObj(info(k), row.get(draft));
  }
  // configure with no option: -name value ...
  Tcl_Obj* all(const Draft& draft) const {
    Tcl_Obj* list = Tcl_NewListObj(0, nullptr);
    for (int k = 0; k < size(); ++k) {
      Tcl_ListObjAppendElement(nullptr, list, Tcl_NewStringObj(info(k).name, -1));
      Tcl_ListObjAppendElement(nullptr, list, get(draft, k));
    }
    return list;
  }
  // `NOUN options`: one dict per row, the defaults read from `defaults`.
  Tcl_Obj* describe(const Draft& defaults) const {
    Tcl_Obj* list = Tcl_NewListObj(0, nullptr);
    for (int k = 0; k < size(); ++k)
      Tcl_ListObjAppendElement(nullptr, list, describeOption(info(k), get(defaults, k)));
    return list;
  }
  // help's option lines, each with its default.
  std::string help(const char* noun, std::initializer_list<const char*> verbs,
                   const Draft& defaults) const {
    std::vector<std::string> texts;
    std::vector<OptionSpec> withDefaults;
    texts.reserve(rows_.size());
    for (int k = 0; k < size(); ++k) {
      Tcl_Obj* value = get(defaults, k);
      Tcl_IncrRefCount(value);
      const std::string shown = info(k).defaultText ? info(k).defaultText : Tcl_GetString(value);
      Tcl_DecrRefCount(value);
      texts.push_back(std::string(info(k).help) + " (default " + (shown.empty() ? "none" : shown) +
                      ")");
    }
    for (int k = 0; k < size(); ++k)
      withDefaults.push_back({info(k).name, info(k).synopsis, texts[std::size_t(k)].c_str()});
    withDefaults.push_back({nullptr, nullptr, nullptr});
    return helpText(noun, verbs, withDefaults.data());
  }
  // `NOUN help` (help's lines) and `NOUN options` (describe) for makeEnsemble;
  // withOptionsVerb false: the noun answers `options` itself, or not at all.
  NounAnswers answers(const char* noun, std::initializer_list<const char*> verbs,
                      const Draft& defaults, bool withOptionsVerb = true) const {
    NounAnswers a{.help = help(noun, verbs, defaults)};
    if (withOptionsVerb) {
      Tcl_Obj* list = describe(defaults);
      Tcl_IncrRefCount(list);
      a.options = Tcl_GetString(list);
      Tcl_DecrRefCount(list);
    }
    return a;
  }

 private:
  std::vector<Option<Draft>> rows_;
  std::vector<OptionSpec> specs_;
  bool inTableOrder_;
};

}  // namespace sf::tcl
