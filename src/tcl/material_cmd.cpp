// material create|configure|cget|names|help
#include "sandflow/tcl/args.hpp"
#include "sandflow/tcl/session.hpp"

namespace sf::tcl {
namespace {

enum Opt {
  kDensity,
  kKn,
  kKs,
  kFriction,
  kRestitution,
  kDamping,
  kNormalForce,
  kBondStiffness,
  kBondStrength,
  kLaw,
  kYoungs,
  kPoisson
};

const OptionSpec kOptions[] = {
    {"-density", "rho", "mass per unit volume (mass = rho x area, per unit thickness)"},
    {"-kn", "k", "normal contact stiffness"},
    {"-ks", "k", "tangential contact stiffness"},
    {"-friction", "mu", "Coulomb friction coefficient"},
    {"-restitution", "e", "target normal restitution, 0..1 (sets the damping)"},
    {"-damping", "c", "fixed normal damping coefficient instead of -restitution"},
    {"-normalforce", "signed|compressive",
     "signed: the dashpot may pull as a contact opens; compressive: clamped at 0"},
    {"-bondstiffness", "k", "stiffness of bonds made of this material"},
    {"-bondstrength", "s", "force at which such bonds break"},
    {"-law", "linear|hertz", "contact law: linear spring-dashpot (default) or Hertz-Mindlin"},
    {"-youngs", "E", "Young's modulus (Hertz-Mindlin)"},
    {"-poisson", "nu", "Poisson's ratio (Hertz-Mindlin)"},
    {nullptr, nullptr, nullptr}};

Tcl_Obj* optionValue(const dem::Material& m, int k) {
  switch (k) {
    case kDensity:
      return newDouble(m.density);
    case kKn:
      return newDouble(m.kn);
    case kKs:
      return newDouble(m.ks);
    case kFriction:
      return newDouble(m.friction);
    case kRestitution:
      return newDouble(m.restitution);
    case kDamping:
      return m.damping >= 0 ? newDouble(m.damping) : Tcl_NewObj();
    case kNormalForce:
      return Tcl_NewStringObj(dem::normalForceNames[int(m.normalForce)], -1);
    case kBondStiffness:
      return newDouble(m.bondStiffness);
    case kBondStrength:
      return newDouble(m.bondStrength);
    case kLaw:
      return Tcl_NewStringObj(dem::contactLawNames[int(m.law)], -1);
    case kYoungs:
      return newDouble(m.youngs);
    default:
      return newDouble(m.poisson);
  }
}

bool applyOptions(Tcl_Interp* interp, int objc, Tcl_Obj* const objv[], int first,
                  dem::Material& m) {
  return parseOptions(interp, objc, objv, first, kOptions, [&](int k, Tcl_Obj* v) {
    if (k == kLaw) {
      int law = 0;
      if (!getChoice(interp, v, "law", dem::contactLawNames, law)) return false;
      m.law = static_cast<dem::ContactLaw>(law);
      return true;
    }
    if (k == kNormalForce) {
      int mode = 0;
      if (!getChoice(interp, v, "normalforce", dem::normalForceNames, mode)) return false;
      m.normalForce = static_cast<dem::NormalForce>(mode);
      return true;
    }
    double d = 0;
    if (!getDouble(interp, v, kOptions[k].name, d)) return false;
    switch (k) {
      case kDensity:
        m.density = d;
        break;
      case kKn:
        m.kn = d;
        break;
      case kKs:
        m.ks = d;
        break;
      case kFriction:
        m.friction = d;
        break;
      case kRestitution:
        m.restitution = d, m.damping = -1;
        break;
      case kDamping:
        if (d < 0)
          return reject(interp, "VALUE DAMPING", "-damping must be >= 0, got " + formatNumber(d));
        m.damping = d;
        break;
      case kBondStiffness:
        m.bondStiffness = d;
        break;
      case kBondStrength:
        m.bondStrength = d;
        break;
      case kYoungs:
        m.youngs = d;
        break;
      default:
        m.poisson = d;
        break;
    }
    // Range checks here, not only in the table, so that errorInfo names the option.
    try {
      dem::validate(m);
    } catch (const Error& e) {
      return reject(interp, e.code(), e.what());
    }
    return true;
  });
}

int MaterialCreate(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc < 2 || objc % 2) {
    Tcl_WrongNumArgs(interp, 1, objv, "NAME ?-option value ...?");
    return TCL_ERROR;
  }
  dem::Material m;
  m.name = Tcl_GetString(objv[1]);
  if (!applyOptions(interp, objc, objv, 2, m)) return TCL_ERROR;
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
    dem::Material m = a.materials()[index];
    if (objc == 2 || objc == 3) {
      if (objc == 3) {
        const int k = optionIndex(interp, objv[2], kOptions);
        if (k < 0) return TCL_ERROR;
        Tcl_SetObjResult(interp, optionValue(m, k));
        return TCL_OK;
      }
      Tcl_Obj* all = Tcl_NewListObj(0, nullptr);
      for (int k = 0; kOptions[k].name; ++k) {
        Tcl_ListObjAppendElement(nullptr, all, Tcl_NewStringObj(kOptions[k].name, -1));
        Tcl_ListObjAppendElement(nullptr, all, optionValue(m, k));
      }
      Tcl_SetObjResult(interp, all);
      return TCL_OK;
    }
    if (objc % 2) {
      Tcl_WrongNumArgs(interp, 1, objv, "NAME ?-option value ...?");
      return TCL_ERROR;
    }
    if (!applyOptions(interp, objc, objv, 2, m)) return TCL_ERROR;
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
    const dem::Material& m = t[t.index(Tcl_GetString(objv[1]))];
    const int k = optionIndex(interp, objv[2], kOptions);
    if (k < 0) return TCL_ERROR;
    Tcl_SetObjResult(interp, optionValue(m, k));
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

int MaterialHelp(ClientData, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc != 1) {
    Tcl_WrongNumArgs(interp, 1, objv, nullptr);
    return TCL_ERROR;
  }
  Tcl_SetObjResult(interp, newString(helpText("material",
                                              {"create NAME ?-option value ...?",
                                               "configure NAME ?-option value ...?",
                                               "cget NAME -option", "names", "help"},
                                              kOptions)));
  return TCL_OK;
}

}  // namespace

void registerMaterialCommands(Tcl_Interp* interp, Session* session) {
  makeEnsemble(interp, "::sf::material",
               {{"create", MaterialCreate},
                {"configure", MaterialConfigure},
                {"cget", MaterialCget},
                {"names", MaterialNames},
                {"help", MaterialHelp}},
               session);
}

}  // namespace sf::tcl
