#include "sandflow/tcl/args.hpp"

#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>
#include <string_view>

#include "remedy.hpp"

namespace sf::tcl {
namespace {

void noteOption(Tcl_Interp* interp, const char* what) {
  const std::string info = std::string("\n    (in ") + what + (what[0] == '-' ? " option)" : ")");
  Tcl_AddErrorInfo(interp, info.c_str());
}

}  // namespace

void noteOptionOnce(Tcl_Interp* interp, const char* option) {
  // Range checks fail without the note the converters add: add it once.
  const std::string note = std::string("(in ") + option + " option)";
  Tcl_Obj* options = Tcl_GetReturnOptions(interp, TCL_ERROR);
  Tcl_IncrRefCount(options);
  Tcl_Obj* key = Tcl_NewStringObj("-errorinfo", -1);
  Tcl_IncrRefCount(key);
  Tcl_Obj* info = nullptr;
  Tcl_DictObjGet(nullptr, options, key, &info);
  const bool noted = info && std::strstr(Tcl_GetString(info), note.c_str());
  Tcl_DecrRefCount(key);
  Tcl_DecrRefCount(options);
  if (!noted) Tcl_AddErrorInfo(interp, ("\n    " + note).c_str());
}

int fail(Tcl_Interp* interp, const std::string& code, const std::string& message) {
  Tcl_SetObjResult(interp, newString(message));
  Tcl_Obj* list = Tcl_NewListObj(0, nullptr);
  Tcl_ListObjAppendElement(nullptr, list, Tcl_NewStringObj("SANDFLOW", -1));
  std::istringstream words(code);
  for (std::string w; words >> w;)
    Tcl_ListObjAppendElement(nullptr, list, Tcl_NewStringObj(w.c_str(), -1));
  Tcl_SetObjErrorCode(interp, list);
  return TCL_ERROR;
}

int fail(Tcl_Interp* interp, const Error& error) {
  return fail(interp, error.code(), withRemedy(error.what(), error.remedy()));
}

bool getDouble(Tcl_Interp* interp, Tcl_Obj* obj, const char* what, double& out) {
  if (Tcl_GetDoubleFromObj(interp, obj, &out) != TCL_OK) {
    noteOption(interp, what);
    return false;
  }
  if (!std::isfinite(out)) {
    fail(interp, "VALUE NUMBER",
         std::string("expected finite number but got \"") + Tcl_GetString(obj) + "\"");
    noteOption(interp, what);
    return false;
  }
  return true;
}

bool getEvery(Tcl_Interp* interp, Tcl_Obj* obj, int& every) {
  if (!getInt(interp, obj, "-every", every)) return false;
  if (every < 1)
    return reject(interp, "VALUE EVERY", "-every must be >= 1, got " + std::to_string(every));
  return true;
}

bool getInt(Tcl_Interp* interp, Tcl_Obj* obj, const char* what, int& out) {
  // Tcl_GetIntFromObj takes 2147483648 to 4294967295 as negative numbers (for
  // unsigned values): refuse what an int cannot hold, in Tcl's words.
  Tcl_WideInt wide = 0;
  if (Tcl_GetWideIntFromObj(nullptr, obj, &wide) == TCL_OK &&
      (wide < std::numeric_limits<int>::min() || wide > std::numeric_limits<int>::max())) {
    const char* message = "integer value too large to represent";
    Tcl_SetObjResult(interp, Tcl_NewStringObj(message, -1));
    Tcl_SetErrorCode(interp, "ARITH", "IOVERFLOW", message, nullptr);
    noteOption(interp, what);
    return false;
  }
  if (Tcl_GetIntFromObj(interp, obj, &out) == TCL_OK) return true;
  noteOption(interp, what);
  return false;
}

bool getBool(Tcl_Interp* interp, Tcl_Obj* obj, const char* what, bool& out) {
  int b = 0;
  if (Tcl_GetBooleanFromObj(interp, obj, &b) != TCL_OK) {
    noteOption(interp, what);
    return false;
  }
  out = b != 0;
  return true;
}

bool getDoubles(Tcl_Interp* interp, Tcl_Obj* obj, const char* what, int count,
                std::vector<double>& out) {
  int n = 0;
  Tcl_Obj** items = nullptr;
  if (Tcl_ListObjGetElements(interp, obj, &n, &items) != TCL_OK) {
    noteOption(interp, what);
    return false;
  }
  if (n != count) {
    fail(interp, "VALUE LIST",
         std::string(what) + " must be a list of " + std::to_string(count) + " numbers, got \"" +
             Tcl_GetString(obj) + "\"");
    noteOption(interp, what);
    return false;
  }
  out.resize(count);
  for (int i = 0; i < count; ++i)
    if (!getDouble(interp, items[i], what, out[i])) return false;
  return true;
}

bool getVec2(Tcl_Interp* interp, Tcl_Obj* obj, const char* what, Vec2& out) {
  std::vector<double> v;
  if (!getDoubles(interp, obj, what, 2, v)) return false;
  out = Vec2(v[0], v[1]);
  return true;
}

bool getChoice(Tcl_Interp* interp, Tcl_Obj* obj, const char* what, const char* const* table,
               int& index) {
  return Tcl_GetIndexFromObjStruct(interp, obj, table, sizeof(const char*), what, TCL_EXACT,
                                   &index) == TCL_OK;
}

bool getElementIds(Tcl_Interp* interp, Tcl_Obj* obj, std::vector<int>& ids) {
  int n = 0;
  Tcl_Obj** items = nullptr;
  if (Tcl_ListObjGetElements(interp, obj, &n, &items) != TCL_OK) return false;
  ids.assign(std::size_t(n), 0);
  for (int i = 0; i < n; ++i)
    if (!getInt(interp, items[i], "-elements", ids[std::size_t(i)])) return false;
  if (ids.empty()) return reject(interp, "VALUE ELEMENTS", "-elements is empty");
  return true;
}

bool getSoleId(Tcl_Interp* interp, int objc, Tcl_Obj* const objv[], const char* what, int& id) {
  if (objc != 2) {
    Tcl_WrongNumArgs(interp, 1, objv, what);
    return false;
  }
  return getInt(interp, objv[1], what, id);
}

int optionIndex(Tcl_Interp* interp, Tcl_Obj* name, const OptionSpec* table) {
  int index = -1;
  if (Tcl_GetIndexFromObjStruct(interp, name, table, sizeof(OptionSpec), "option", TCL_EXACT,
                                &index) != TCL_OK)
    return -1;
  return index;
}

bool parseOptions(Tcl_Interp* interp, int objc, Tcl_Obj* const objv[], int first,
                  const OptionSpec* table, const std::function<bool(int, Tcl_Obj*)>& handle) {
  for (int i = first; i < objc; i += 2) {
    const int index = optionIndex(interp, objv[i], table);
    if (index < 0) return false;
    if (i + 1 >= objc) {
      fail(interp, "VALUE MISSING",
           std::string("value for \"") + Tcl_GetString(objv[i]) + "\" missing");
      return false;
    }
    if (!handle(index, objv[i + 1])) {
      noteOptionOnce(interp, table[index].name);
      return false;
    }
  }
  return true;
}

Tcl_Obj* newDouble(double v) {
  return Tcl_NewDoubleObj(v);
}

Tcl_Obj* newVec2(const Vec2& v) {
  Tcl_Obj* items[2] = {Tcl_NewDoubleObj(v.x()), Tcl_NewDoubleObj(v.y())};
  return Tcl_NewListObj(2, items);
}

Tcl_Obj* newString(const std::string& s) {
  return Tcl_NewStringObj(s.data(), static_cast<int>(s.size()));
}

Tcl_Obj* newDict(std::initializer_list<std::pair<const char*, Tcl_Obj*>> items) {
  Tcl_Obj* d = Tcl_NewDictObj();
  for (const auto& [k, v] : items) dictPut(d, k, v);
  return d;
}

void dictPut(Tcl_Obj* dict, const char* key, Tcl_Obj* value) {
  Tcl_DictObjPut(nullptr, dict, Tcl_NewStringObj(key, -1), value);
}

std::string helpText(const char* noun, std::initializer_list<const char*> verbs,
                     const OptionSpec* options) {
  std::string text;
  for (const char* v : verbs) text += std::string(noun) + " " + v + "\n";
  if (options && options->name) {
    text += "options:\n";
    for (const OptionSpec* o = options; o->name; ++o)
      text += std::string("  ") + o->name + " " + o->synopsis + "\n      " + o->help + "\n";
  }
  if (!text.empty()) text.pop_back();
  return text;
}

bool answerHelp(Tcl_Interp* interp, int objc, Tcl_Obj* const objv[], const std::string& text) {
  if (objc != 2 || std::string_view(Tcl_GetString(objv[1])) != "help") return false;
  Tcl_SetObjResult(interp, newString(text));
  return true;
}

namespace {

void ensembleOf(Tcl_Interp* interp, const char* qualifiedName, const std::vector<Verb>& verbs,
                ClientData data) {
  Tcl_Namespace* ns = Tcl_FindNamespace(interp, qualifiedName, nullptr, 0);
  if (!ns) ns = Tcl_CreateNamespace(interp, qualifiedName, nullptr, nullptr);
  Tcl_Obj* map = Tcl_NewDictObj();
  for (const Verb& v : verbs) {
    const std::string full = std::string(qualifiedName) + "::" + v.name;
    if (v.proc) Tcl_CreateObjCommand(interp, full.c_str(), v.proc, data, nullptr);
    Tcl_DictObjPut(nullptr, map, Tcl_NewStringObj(v.name, -1), Tcl_NewStringObj(full.c_str(), -1));
  }
  Tcl_Command ensemble = Tcl_CreateEnsemble(interp, qualifiedName, ns, 0);
  Tcl_SetEnsembleMappingDict(interp, ensemble, map);
}

// `NOUN help` or `NOUN options`: the fixed text held as the command's data.
int AnswerText(ClientData text, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc != 1) {
    Tcl_WrongNumArgs(interp, 1, objv, nullptr);
    return TCL_ERROR;
  }
  Tcl_SetObjResult(interp, newString(*static_cast<const std::string*>(text)));
  return TCL_OK;
}

void answerVerb(Tcl_Interp* interp, const std::string& full, std::string text) {
  Tcl_CreateObjCommand(interp, full.c_str(), AnswerText, new std::string(std::move(text)),
                       [](ClientData text) { delete static_cast<std::string*>(text); });
}

}  // namespace

void makeEnsemble(Tcl_Interp* interp, const char* qualifiedName, std::initializer_list<Verb> verbs,
                  ClientData data, NounAnswers answers) {
  std::vector<Verb> all(verbs);
  all.push_back({"help", nullptr});
  if (!answers.options.empty()) all.push_back({"options", nullptr});
  const std::string prefix = std::string(qualifiedName) + "::";
  Tcl_CreateNamespace(interp, qualifiedName, nullptr, nullptr);
  answerVerb(interp, prefix + "help", std::move(answers.help));
  if (!answers.options.empty()) answerVerb(interp, prefix + "options", std::move(answers.options));
  ensembleOf(interp, qualifiedName, all, data);
}

void makeEnsemble(Tcl_Interp* interp, const char* qualifiedName, std::initializer_list<Verb> verbs,
                  ClientData data) {
  ensembleOf(interp, qualifiedName, verbs, data);
}

}  // namespace sf::tcl
