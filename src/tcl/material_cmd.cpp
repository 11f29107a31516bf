// material create|configure|cget|names|options|help
#include "sandflow/tcl/args.hpp"
#include "sandflow/tcl/option_table.hpp"
#include "sandflow/tcl/session.hpp"

namespace sf::tcl {
namespace {

using dem::Material;
using Row = Option<Material>;

// "-restitution must be between 0 and 1, got 1.5": the words of dem::validate,
// which keeps the same ranges as the invariant of every material it stores.
std::string restitutionRange(double e) {
  return "-restitution must be between 0 and 1, got " + formatNumber(e);
}
std::string poissonRange(double nu) {
  return "-poisson must be between -1 and 0.5, got " + formatNumber(nu);
}

constexpr Range kPositive{.min = 0, .minOpen = true};
constexpr Range kNonNegative{.min = 0};

// A plain real field of the material.
Row realRow(OptionInfo info, double Material::*field) {
  return memberRow(info, field);
}

const OptionTable<Material> kOptions{
    realRow({.name = "-density",
             .synopsis = "rho",
             .help = "mass per unit volume (mass = rho x area, per unit thickness)",
             .unit = "mass/length^2",
             .range = kPositive},
            &Material::density),
    realRow({.name = "-kn",
             .synopsis = "k",
             .help = "normal contact stiffness",
             .unit = "force/length",
             .range = kPositive},
            &Material::kn),
    realRow({.name = "-ks",
             .synopsis = "k",
             .help = "tangential contact stiffness",
             .unit = "force/length",
             .range = kNonNegative},
            &Material::ks),
    realRow({.name = "-friction",
             .synopsis = "mu",
             .help = "Coulomb friction coefficient",
             .range = kNonNegative},
            &Material::friction),
    Row{.info = {.name = "-restitution",
                 .synopsis = "e",
                 .help = "target normal restitution (sets the damping)",
                 .range = {.min = 0, .max = 1},
                 .outOfRange = restitutionRange},
        .get = [](const Material& m) { return realValue(m.restitution); },
        .set = [](Material& m, const OptionValue& v) { m.restitution = v.real, m.damping = -1; }},
    // The kernel keeps "none" as a negative damping, so it cannot refuse one:
    // the range is this layer's. {} (what cget shows then) goes back to it.
    Row{.info = {.name = "-damping",
                 .synopsis = "c",
                 .help = "fixed normal damping coefficient instead of -restitution; {}: none, "
                         "-restitution rules",
                 .unit = "mass/time",
                 .range = kNonNegative,
                 .orEmpty = true},
        .get =
            [](const Material& m) { return m.damping >= 0 ? realValue(m.damping) : emptyValue(); },
        .set = [](Material& m, const OptionValue& v) { m.damping = v.empty ? -1 : v.real; }},
    Row{.info = {.name = "-normalforce",
                 .synopsis = "signed|compressive",
                 .help =
                     "signed: the dashpot may pull as a contact opens; compressive: clamped at 0",
                 .kind = ValueKind::choice,
                 .choices = dem::normalForceNames,
                 .what = "normalforce"},
        .get = [](const Material& m) { return choiceValue(int(m.normalForce)); },
        .set = [](Material& m,
                  const OptionValue& v) { m.normalForce = dem::NormalForce(v.choice); }},
    realRow({.name = "-bondstiffness",
             .synopsis = "k",
             .help = "stiffness of bonds made of this material",
             .unit = "force/length",
             .range = kNonNegative},
            &Material::bondStiffness),
    realRow({.name = "-bondstrength",
             .synopsis = "s",
             .help = "force at which such bonds break",
             .unit = "force",
             .range = kNonNegative},
            &Material::bondStrength),
    Row{.info = {.name = "-law",
                 .synopsis = "linear|hertz",
                 .help = "contact law: linear spring-dashpot or Hertz-Mindlin",
                 .kind = ValueKind::choice,
                 .choices = dem::contactLawNames,
                 .what = "law"},
        .get = [](const Material& m) { return choiceValue(int(m.law)); },
        .set = [](Material& m, const OptionValue& v) { m.law = dem::ContactLaw(v.choice); }},
    realRow({.name = "-youngs",
             .synopsis = "E",
             .help = "Young's modulus (Hertz-Mindlin)",
             .unit = "force/length",
             .range = kPositive},
            &Material::youngs),
    Row{.info = {.name = "-poisson",
                 .synopsis = "nu",
                 .help = "Poisson's ratio (Hertz-Mindlin)",
                 .range = {.min = -1, .max = 0.5, .minOpen = true, .maxOpen = true},
                 .outOfRange = poissonRange},
        .get = [](const Material& m) { return realValue(m.poisson); },
        .set = [](Material& m, const OptionValue& v) { m.poisson = v.real; }},
};

// A new material's settings, for help's and `material options`' defaults.
const Material& defaults() {
  static const Material d{"default"};
  return d;
}

// The rows check every value; the material table validates again when it
// stores one (dem::validate, the same ranges), as its invariant.
int MaterialCreate(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc < 2 || objc % 2) {
    Tcl_WrongNumArgs(interp, 1, objv, "NAME ?-option value ...?");
    return TCL_ERROR;
  }
  Material m;
  m.name = Tcl_GetString(objv[1]);
  if (!kOptions.apply(interp, objc, objv, 2, m)) return TCL_ERROR;
  return guarded(interp, [&] {
    sessionOf(data).manager.assembly().materials().add(m);
    Tcl_SetObjResult(interp, objv[1]);
    return TCL_OK;
  });
}

int MaterialConfigure(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc < 2) {
    Tcl_WrongNumArgs(interp, 1, objv, "NAME ?-option value ...?");
    return TCL_ERROR;
  }
  dem::Assembly& a = sessionOf(data).manager.assembly();
  return guarded(interp, [&] {
    const int index = a.materials().index(Tcl_GetString(objv[1]));
    Material m = a.materials()[index];
    if (objc == 2) {
      Tcl_SetObjResult(interp, kOptions.all(m));
      return TCL_OK;
    }
    if (objc == 3) {
      const int k = optionIndex(interp, objv[2], kOptions.specs());
      if (k < 0) return TCL_ERROR;
      Tcl_SetObjResult(interp, kOptions.get(m, k));
      return TCL_OK;
    }
    if (objc % 2) {
      Tcl_WrongNumArgs(interp, 1, objv, "NAME ?-option value ...?");
      return TCL_ERROR;
    }
    if (!kOptions.apply(interp, objc, objv, 2, m)) return TCL_ERROR;
    for (int s = 0; s < a.bodies().size(); ++s)  // a new density must leave every mass finite
      if (a.bodies().material[s] == index) dem::Assembly::checkMass(*a.bodies().shape[s], m);
    a.materials().replace(index, m);
    for (int s = 0; s < a.bodies().size(); ++s)
      if (a.bodies().material[s] == index) a.updateMass(s);
    return TCL_OK;
  });
}

int MaterialCget(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc != 3) {
    Tcl_WrongNumArgs(interp, 1, objv, "NAME -option");
    return TCL_ERROR;
  }
  return guarded(interp, [&] {
    const dem::MaterialTable& t = sessionOf(data).manager.assembly().materials();
    const Material& m = t[t.index(Tcl_GetString(objv[1]))];
    const int k = optionIndex(interp, objv[2], kOptions.specs());
    if (k < 0) return TCL_ERROR;
    Tcl_SetObjResult(interp, kOptions.get(m, k));
    return TCL_OK;
  });
}

int MaterialNames(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc != 1) {
    Tcl_WrongNumArgs(interp, 1, objv, nullptr);
    return TCL_ERROR;
  }
  Tcl_Obj* names = Tcl_NewListObj(0, nullptr);
  for (const std::string& n : sessionOf(data).manager.assembly().materials().names())
    Tcl_ListObjAppendElement(nullptr, names, newString(n));
  Tcl_SetObjResult(interp, names);
  return TCL_OK;
}

}  // namespace

void registerMaterialCommands(Tcl_Interp* interp, Session* session) {
  makeEnsemble(interp, "::sf::material",
               {{"create", MaterialCreate},
                {"configure", MaterialConfigure},
                {"cget", MaterialCget},
                {"names", MaterialNames}},
               session,
               kOptions.answers("material",
                                {"create NAME ?-option value ...?",
                                 "configure NAME ?-option value ...?", "cget NAME -option", "names",
                                 "options   -> the options as dicts: name type unit min "
                                 "max choices default ...",
                                 "help"},
                                defaults()));
}

}  // namespace sf::tcl
