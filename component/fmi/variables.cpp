#include "fmi/variables.hpp"

#include <algorithm>

#include "peristep.h"

namespace peristep::fmi {

namespace {

using C = Causality;
using V = Variability;
using I = Initial;
using T = VarType;

constexpr fmi3ValueReference kNx = PERISTEP_VR_NX, kNy = PERISTEP_VR_NY, kModes = PERISTEP_VR_NMODES;

// Images are [ny][nx]: the outer dimension is ny (FMI arrays are row-major).
std::vector<fmi3ValueReference> image() { return {kNy, kNx}; }

std::vector<Variable> makeTable() {
  return {
      {.name = "time", .vr = PERISTEP_VR_TIME, .type = T::Float64, .causality = C::Independent,
       .variability = V::Continuous, .initial = I::Default,
       .description = "Simulation time: each communication step is one quasi-static load increment", .unit = "s"},

      {.name = "nx", .vr = PERISTEP_VR_NX, .type = T::UInt64, .causality = C::StructuralParameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Points per side in x (arrays [ny][nx] are images, x varying fastest)", .start = "33",
       .min = Bound{2}, .max = Bound{65536}},
      {.name = "ny", .vr = PERISTEP_VR_NY, .type = T::UInt64, .causality = C::StructuralParameter,
       .variability = V::Fixed, .initial = I::Exact, .description = "Points per side in y", .start = "33",
       .min = Bound{2}, .max = Bound{65536}},
      {.name = "nModes", .vr = PERISTEP_VR_NMODES, .type = T::UInt64, .causality = C::StructuralParameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Length of xi; at least the number of random coordinates of the scene (smooth 1, composite 2)",
       .start = "1", .min = Bound{1}, .max = Bound{1024}},

      {.name = "scene", .vr = PERISTEP_VR_SCENE, .type = T::Enumeration, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact, .description = "Built-in scene",
       .declaredType = "PeriStep.Scene", .start = "1"},
      {.name = "Lx", .vr = PERISTEP_VR_LX, .type = T::Float64, .causality = C::Parameter, .variability = V::Fixed,
       .initial = I::Exact,
       .description = "Domain width, > 0: the domain is [-Lx/2, Lx/2] x [-Ly/2, Ly/2] and Lx/(nx-1) must equal "
                      "Ly/(ny-1)",
       .unit = "m", .start = "1", .min = Bound{0, true}},
      {.name = "Ly", .vr = PERISTEP_VR_LY, .type = T::Float64, .causality = C::Parameter, .variability = V::Fixed,
       .initial = I::Exact, .description = "Domain height, > 0", .unit = "m", .start = "1",
       .min = Bound{0, true}},
      {.name = "deltaOverH", .vr = PERISTEP_VR_DELTA_OVER_H, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Peridynamic horizon over grid spacing, 1 <= delta/h <= 20", .start = "3", .min = Bound{1},
       .max = Bound{20}},  // the collar is 2 delta wide: an unbounded horizon would overflow the point count
      {.name = "poissonRatio", .vr = PERISTEP_VR_POISSON_RATIO, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact, .description = "Poisson's ratio (plane strain), -1 < nu < 0.5",
       .start = "0.3", .min = Bound{-1, true}, .max = Bound{0.5, true}},
      {.name = "modulusContrast", .vr = PERISTEP_VR_MODULUS_CONTRAST, .type = T::Float64,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "Composite scene: Young's modulus right of x = 0 over left, > 0", .start = "2",
       .min = Bound{0, true}},
      {.name = "jitter", .vr = PERISTEP_VR_JITTER, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Random displacement of every point as a fraction of h, 0 <= jitter < 0.5", .start = "0",
       .min = Bound{0}, .max = Bound{0.5, true}},
      {.name = "seed", .vr = PERISTEP_VR_SEED, .type = T::UInt64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact, .description = "Seed of the point jitter", .start = "1"},
      {.name = "linearSolver", .vr = PERISTEP_VR_LINEAR_SOLVER, .type = T::Enumeration, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact, .description = "Sparse solver of the (u, theta) system",
       .declaredType = "PeriStep.LinearSolver", .start = "1"},
      {.name = "xi", .vr = PERISTEP_VR_XI, .type = T::Float64, .causality = C::Parameter, .variability = V::Fixed,
       .initial = I::Exact,
       .description = "Standardized random coordinates of this sample (physical coordinate = xiScale * xi)",
       .start = "0", .dimensions = {kModes}},
      {.name = "crystalFraction", .vr = PERISTEP_VR_CRYSTAL_FRACTION, .type = T::Float64,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "Glass-ceramic scene: crystal area fraction f in [0, 1] (ellipses added until reached)",
       .start = "0.2", .min = Bound{0, false}, .max = Bound{1, false}},

      {.name = "xiDistribution", .vr = PERISTEP_VR_XI_DISTRIBUTION, .type = T::Int32,
       .causality = C::CalculatedParameter, .variability = V::Fixed, .initial = I::Calculated,
       .description = "Law of each coordinate xi: 0 normal, 1 uniform", .dimensions = {kModes}},
      {.name = "xiScale", .vr = PERISTEP_VR_XI_SCALE, .type = T::Float64, .causality = C::CalculatedParameter,
       .variability = V::Fixed, .initial = I::Calculated,
       .description = "Scale of each coordinate: physical coordinate = xiScale * xi", .dimensions = {kModes}},
      {.name = "x", .vr = PERISTEP_VR_X, .type = T::Float64, .causality = C::CalculatedParameter,
       .variability = V::Fixed, .initial = I::Calculated, .description = "x coordinate of each domain point",
       .unit = "m", .dimensions = image()},
      {.name = "y", .vr = PERISTEP_VR_Y, .type = T::Float64, .causality = C::CalculatedParameter,
       .variability = V::Fixed, .initial = I::Calculated, .description = "y coordinate of each domain point",
       .unit = "m", .dimensions = image()},

      {.name = "loadFactor", .vr = PERISTEP_VR_LOAD_FACTOR, .type = T::Float64, .causality = C::Input,
       .variability = V::Continuous, .initial = I::Default,
       .description = "Scale of the body force and boundary data (scenes smooth, composite, interfaceCrack); every "
                      "step solves at its current value",
       .start = "1"},
      {.name = "loadDisplacement", .vr = PERISTEP_VR_LOAD_DISPLACEMENT, .type = T::Float64, .causality = C::Input,
       .variability = V::Continuous, .initial = I::Default,
       .description = "Opening U_D of the glass-ceramic plate: the top collar moves by +U_D, the bottom by -U_D; "
                      "every step breaks bonds until equilibrium at its current value",
       .unit = "m", .start = "0"},

      {.name = "ux", .vr = PERISTEP_VR_UX, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated, .description = "Displacement in x of each domain point",
       .unit = "m", .dimensions = image()},
      {.name = "uy", .vr = PERISTEP_VR_UY, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated, .description = "Displacement in y of each domain point",
       .unit = "m", .dimensions = image()},
      {.name = "damage", .vr = PERISTEP_VR_DAMAGE, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Damage of each domain point, 000:(3.23): broken fraction of its material bonds; 0 where "
                      "nothing can break",
       .dimensions = image()},
      {.name = "youngsModulus", .vr = PERISTEP_VR_YOUNGS_MODULUS, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Young's modulus of each domain point (the material field, e.g. the microstructure)",
       .unit = "Pa", .dimensions = image()},
      {.name = "reactionForce", .vr = PERISTEP_VR_REACTION_FORCE, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Force per unit thickness of the top collar on the specimen (glass-ceramic); 0 where the "
                      "scene defines none",
       .unit = "N/m"},
      {.name = "crackLength", .vr = PERISTEP_VR_CRACK_LENGTH, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Crack length grown by loading, from broken bonds (glass-ceramic); 0 otherwise", .unit = "m"},
      {.name = "brokenBonds", .vr = PERISTEP_VR_BROKEN_BONDS, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Number of broken material bonds, pre-crack included; 0 where nothing can break"},
      {.name = "strainEnergy", .vr = PERISTEP_VR_STRAIN_ENERGY, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Elastic strain energy per unit thickness; 0: not computed by the current scenes",
       .unit = "J/m"},
      {.name = "fractureEnergy", .vr = PERISTEP_VR_FRACTURE_ENERGY, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Fracture energy G1 L1 + G2 L2 + Gi Li per unit thickness (glass-ceramic, 000:(5.2)); 0 "
                      "otherwise",
       .unit = "J/m"},
      {.name = "toughnessKIC", .vr = PERISTEP_VR_TOUGHNESS_KIC, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Fracture toughness K_IC in Pa m^0.5 from 000:(5.2)-(5.3) (glass-ceramic); 0 otherwise"},
      {.name = "errorL2", .vr = PERISTEP_VR_ERROR_L2, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "L2 error of the displacement against the scene's exact solution; 0 without one",
       .unit = "m"},
  };
}

}  // namespace

const std::vector<Variable>& variables() {
  static const std::vector<Variable> table = makeTable();
  return table;
}

const Variable* findVariable(fmi3ValueReference vr) {
  const auto& t = variables();
  const auto it = std::find_if(t.begin(), t.end(), [vr](const Variable& v) { return v.vr == vr; });
  return it == t.end() ? nullptr : &*it;
}

const std::vector<EnumerationType>& enumerationTypes() {
  static const std::vector<EnumerationType> types{
      {"PeriStep.Scene",
       "Built-in scenes",
       {{"smooth", PERISTEP_SCENE_SMOOTH, "Smooth manufactured solution, one random coordinate (Fan et al., Test 1)"},
        {"composite", PERISTEP_SCENE_COMPOSITE,
         "Bimaterial composite, two random coordinates (Fan et al., Test 2)"},
        {"interfaceCrack", PERISTEP_SCENE_INTERFACE_CRACK,
         "Crack on a bimaterial interface, two random coordinates (Fan et al., Test 3)"},
        {"glassCeramic", PERISTEP_SCENE_GLASS_CERAMIC,
         "Pre-cracked glass-ceramic plate opened by loadDisplacement; microstructure from seed (Fan et al., Sec. 5)"}}},
      {"PeriStep.LinearSolver",
       "Sparse solvers of the (u, theta) system",
       {{"umfpack", PERISTEP_LINEAR_SOLVER_UMFPACK, "UMFPACK, 64-bit indices, METIS ordering"},
        {"umfpackAmd", PERISTEP_LINEAR_SOLVER_UMFPACK_AMD, "UMFPACK with its default AMD/COLAMD ordering"},
        {"sparseLU", PERISTEP_LINEAR_SOLVER_SPARSE_LU, "Eigen SparseLU"},
        {"bicgstabIlut", PERISTEP_LINEAR_SOLVER_BICGSTAB_ILUT, "Eigen BiCGSTAB with an ILUT preconditioner"}}},
  };
  return types;
}

const EnumerationType* findEnumeration(std::string_view name) {
  const auto& t = enumerationTypes();
  const auto it = std::find_if(t.begin(), t.end(), [name](const EnumerationType& e) { return e.name == name; });
  return it == t.end() ? nullptr : &*it;
}

const std::vector<UnitDefinition>& unitDefinitions() {
  // N/m = kg s^-2 and J/m = kg m s^-2 (per unit thickness of the plane-strain body).
  static const std::vector<UnitDefinition> units{
      {.name = "s", .s = 1}, {.name = "m", .m = 1}, {.name = "N/m", .kg = 1, .s = -2},
      {.name = "Pa", .kg = 1, .m = -1, .s = -2},
      {.name = "J/m", .kg = 1, .m = 1, .s = -2}};
  return units;
}

std::string_view typeName(VarType t) {
  switch (t) {
    case VarType::Float64: return "Float64";
    case VarType::Int32: return "Int32";
    case VarType::UInt64: return "UInt64";
    case VarType::Enumeration: return "Enumeration";
  }
  return "?";
}

std::string_view causalityName(Causality c) {
  switch (c) {
    case Causality::Independent: return "independent";
    case Causality::StructuralParameter: return "structuralParameter";
    case Causality::Parameter: return "parameter";
    case Causality::CalculatedParameter: return "calculatedParameter";
    case Causality::Input: return "input";
    case Causality::Output: return "output";
  }
  return "?";
}

std::string_view variabilityName(Variability v) { return v == Variability::Fixed ? "fixed" : "continuous"; }

std::string label(const Variable& v) { return std::string(v.name) + " (vr " + std::to_string(v.vr) + ")"; }

}  // namespace peristep::fmi
