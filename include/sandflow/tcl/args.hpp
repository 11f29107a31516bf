#pragma once
// Argument conversion and error reporting shared by every command. Messages use
// Tcl's own phrasing; errorCode is "SANDFLOW <CLASS> <DETAIL>"; errorInfo says
// which option a bad value came from.
#include <tcl.h>

#include <exception>
#include <functional>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "sandflow/core/error.hpp"
#include "sandflow/geometry/vec2.hpp"

namespace sf::tcl {

// A row of an option table. `name` must come first (Tcl_GetIndexFromObjStruct).
struct OptionSpec {
  const char* name;
  const char* synopsis;  // value form, e.g. "{x y}"
  const char* help;
};

// Sets the result and errorCode and returns TCL_ERROR.
int fail(Tcl_Interp* interp, const std::string& code, const std::string& message);
int fail(Tcl_Interp* interp, const Error& error);
// The same, for converters that return bool: sets the error and returns false.
inline bool reject(Tcl_Interp* interp, const std::string& code, const std::string& message) {
  fail(interp, code, message);
  return false;
}

// Adds "(in OPTION option)" to errorInfo unless it is there already.
void noteOptionOnce(Tcl_Interp* interp, const char* option);

// Converters: on failure they leave Tcl's message, add "(in OPTION option)" to
// errorInfo and return false. `what` names the option or argument.
bool getDouble(Tcl_Interp* interp, Tcl_Obj* obj, const char* what, double& out);
bool getInt(Tcl_Interp* interp, Tcl_Obj* obj, const char* what, int& out);
bool getBool(Tcl_Interp* interp, Tcl_Obj* obj, const char* what, bool& out);
// The K of "-every K" (run, output csv, output movie, record): an int >= 1.
bool getEvery(Tcl_Interp* interp, Tcl_Obj* obj, int& every);
bool getVec2(Tcl_Interp* interp, Tcl_Obj* obj, const char* what, Vec2& out);
bool getDoubles(Tcl_Interp* interp, Tcl_Obj* obj, const char* what, int count,
                std::vector<double>& out);
// `table` is a static, null-terminated list of names; the error reads
// `bad WHAT "x": must be a, b, or c`.
bool getChoice(Tcl_Interp* interp, Tcl_Obj* obj, const char* what, const char* const* table,
               int& index);

// Parses "-option value" pairs from objv[first..objc). Each option is converted
// by `handle(index, value)`; returns false (with the Tcl error set) on the first
// problem. Duplicates are allowed; the last one wins, as in Tk.
bool parseOptions(Tcl_Interp* interp, int objc, Tcl_Obj* const objv[], int first,
                  const OptionSpec* table, const std::function<bool(int, Tcl_Obj*)>& handle);
// The value of -elements: a non-empty list of element ids (not looked up).
bool getElementIds(Tcl_Interp* interp, Tcl_Obj* obj, std::vector<int>& ids);
// "VERB ID": objv holds just the id, named `what` in the messages ("ID", "BID").
bool getSoleId(Tcl_Interp* interp, int objc, Tcl_Obj* const objv[], const char* what, int& id);
// Index of one option name, or -1 with the "bad option" error set.
int optionIndex(Tcl_Interp* interp, Tcl_Obj* name, const OptionSpec* table);

Tcl_Obj* newDouble(double v);
Tcl_Obj* newVec2(const Vec2& v);
Tcl_Obj* newString(const std::string& s);
// A dict from key/value pairs, in order.
Tcl_Obj* newDict(std::initializer_list<std::pair<const char*, Tcl_Obj*>> items);
void dictPut(Tcl_Obj* dict, const char* key, Tcl_Obj* value);

// "help" text for an ensemble: its verbs and options.
std::string helpText(const char* noun, std::initializer_list<const char*> verbs,
                     const OptionSpec* options);
// `NOUN help` of a command that is not an ensemble (record, plot, run): true,
// with `text` (its table's help) as the result, when objv is exactly {NOUN help}.
bool answerHelp(Tcl_Interp* interp, int objc, Tcl_Obj* const objv[], const std::string& text);

// Creates the ensemble ::sf::NOUN whose verbs are the given commands.
struct Verb {
  const char* name;
  Tcl_ObjCmdProc* proc;
};
void makeEnsemble(Tcl_Interp* interp, const char* qualifiedName, std::initializer_list<Verb> verbs,
                  ClientData data);
// What `NOUN help` and `NOUN options` answer, made once from the noun's option
// table (OptionTable::answers): fixed texts, so that no noun writes these verbs.
struct NounAnswers {
  std::string help = {};     // the help verb's text
  std::string options = {};  // the options verb's list of dicts; "" where the noun has none
};
// makeEnsemble, with the verbs help and (unless answers.options is "") options
// answering the texts.
void makeEnsemble(Tcl_Interp* interp, const char* qualifiedName, std::initializer_list<Verb> verbs,
                  ClientData data, NounAnswers answers);

// Runs `body`, turning an sf::Error (or a failed allocation) into a Tcl error.
template <class Body>
int guarded(Tcl_Interp* interp, Body&& body) {
  try {
    return body();
  } catch (const Error& e) {
    return fail(interp, e);
  } catch (const std::bad_alloc&) {
    return fail(interp, "RESOURCE MEMORY", "out of memory");
  } catch (const std::exception& e) {
    // A fault of sandflow's, not of the input: a Tcl error still, never a crash.
    return fail(interp, "INTERNAL", std::string("internal error (please report): ") + e.what());
  }
}

}  // namespace sf::tcl
