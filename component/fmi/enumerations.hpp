#pragma once
// The FMI enumeration value (api/peristep.h) of every option that selects C++ code: the one place where the
// two are paired. Names and descriptions come from the option's table (core/option_table.hpp), beside the
// code it selects; the scenes' table is here, as its descriptions speak of the FMU's experiment and steps.
// The variable table takes the <Item>s from here and the model binding turns the value an importer set into
// the C++ value, so an option is never spelled as a string between the two.
#include <array>
#include <cstdint>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "core/errors.hpp"
#include "core/option_table.hpp"
#include "fmi/variables.hpp"
#include "peristep.h"
#include "scenes/scene_model.hpp"

namespace peristep::fmi {

template <class Kind>
struct EnumerationValue {
  std::int64_t value;
  Kind kind;
};

inline constexpr std::array<EnumerationValue<SceneId>, 11> kSceneValues{{
    {PERISTEP_SCENE_SMOOTH, SceneId::Smooth},
    {PERISTEP_SCENE_COMPOSITE, SceneId::Composite},
    {PERISTEP_SCENE_INTERFACE_CRACK, SceneId::InterfaceCrack},
    {PERISTEP_SCENE_GLASS_CERAMIC, SceneId::GlassCeramic},
    {PERISTEP_SCENE_PLEXIGLASS_CRACK, SceneId::PlexiglassCrack},
    {PERISTEP_SCENE_BENDING_ONE_NOTCH, SceneId::BendingOneNotch},
    {PERISTEP_SCENE_BENDING_TWO_NOTCHES, SceneId::BendingTwoNotches},
    {PERISTEP_SCENE_KL_PLATE, SceneId::KlPlate},
    {PERISTEP_SCENE_SPECIMEN, SceneId::Specimen},
    {PERISTEP_SCENE_GAMUT_BAR, SceneId::GamutBar},
    {PERISTEP_SCENE_LEARNED_FRACTURE, SceneId::LearnedFracture},
}};

// The scenes' names and descriptions: FMI's own (they give the DefaultExperiment and step sizes that fit).
inline constexpr std::array<Option<SceneId>, 11> kSceneOptions{{
    {SceneId::Smooth, "smooth",
     "Smooth manufactured solution, one random coordinate (Fan et al., Test 1): the specimen with specimenModel "
     "elastic, every side held, exactSolution smooth; quasi-static: the DefaultExperiment fits"},
    {SceneId::Composite, "composite",
     "Bimaterial composite, two random coordinates (Fan et al., Test 2): the specimen with specimenModel "
     "elastic, every side held, exactSolution composite; quasi-static: the DefaultExperiment fits"},
    {SceneId::InterfaceCrack, "interfaceCrack",
     "Crack on a bimaterial interface, two random coordinates (Fan et al., Test 3): the specimen with "
     "specimenModel elastic, every side held, exactSolution interfaceCrack and the crack from 2 delta beyond the "
     "left edge to the origin; quasi-static: the DefaultExperiment fits"},
    {SceneId::GlassCeramic, "glassCeramic",
     "Pre-cracked glass-ceramic plate opened by loadDisplacement; microstructure from seed or its PCA field "
     "(Fan et al., Sec. 5); a preset of the specimen scene (materialField glassCeramic, grips bottom and top, "
     "reactions as the specimen's); quasi-static, any step size: the paper's plate is Lx = 800e-6 m, Ly = 400e-6 m "
     "(e.g. nx = 51, ny = 26), opened in increments of 4e-9 m, one per step"},
    {SceneId::PlexiglassCrack, "plexiglassCrack",
     "Dynamic crack in a pre-cracked Plexiglass square, bottom strips pulled apart (Jha-Lipton, Sec. 6.1); "
     "communication step 2e-6 s, stop time 34e-6 s (500 internal steps of 0.004 us per step)"},
    {SceneId::BendingOneNotch, "bendingOneNotch",
     "Dynamic three-point bending of a beam with one pre-crack (Jha-Lipton, Sec. 6.2); communication step "
     "1e-5 s, stop time 3.5e-4 s (about 2857 internal steps of 0.0035 us per step)"},
    {SceneId::BendingTwoNotches, "bendingTwoNotches",
     "Dynamic three-point bending of a beam with two pre-cracks (Jha-Lipton, Sec. 6.2); communication step "
     "1e-5 s, stop time 3.5e-4 s (about 2857 internal steps of 0.0035 us per step)"},
    {SceneId::KlPlate, "klPlate",
     "Plate with a Karhunen-Loeve random Young's modulus (nModes coordinates), stretched by loadFactor: the "
     "specimen with specimenModel elastic, materialField klField, E = 1, every side held, collarDuyDy = 0.01; "
     "quasi-static: the DefaultExperiment fits"},
    {SceneId::Specimen, "specimen",
     "The importer's specimen: plate Lx x Ly on the vertex grid, material maps materialYoungsModulus, "
     "materialPoissonRatio, materialFractureEnergy, pre-cracks crackX0..crackY1, grips gripLeft..gripTop "
     "moved by loadFactor; specimenModel quasiStatic: brittle fracture (000 Sec. 3.3), every step breaks "
     "bonds until equilibrium at its load; elastic: the same without fracture; dynamic: the state-based model "
     "of 001 over each communication step, the held grips moving at loadFactor * (gripVx, gripVy)"},
    {SceneId::GamutBar, "gamutBar",
     "1D stochastic deformation-gamut bar (Desai, paper 002 Sec. 4): realization seed of gamutBonds bonds, "
     "gamutMaterial, gamutGrid, scatter of 002:(26); fixed at x = 0, pulled at x = L. gamutProtocol "
     "monotonic: every step moves the end stress to loadFactor * sigma_f; cyclic: every step of any size "
     "takes the next of the protocol's 53 force steps, and cyclicExponent, cyclicCoefficient hold n', K' "
     "after the 53rd; quasi-static, no image outputs"},
    {SceneId::LearnedFracture, "learnedFracture",
     "The LPS model learned from molecular dynamics of graphene (You et al., paper 003) predicting an MD "
     "fracture sample (learnedSample) from its frame 0: the kernel, moduli and s0 learned by learn_lps (or s0 = "
     "learnedCriticalStretch), edges or body force driven by the frames; needs the FMU's resources. nx, ny: the "
     "sample's grid (20 x 20, or 31 x 31 for trainingFine); each communication step is a whole number of MD "
     "frame intervals of 4.95e-14 s (8 explicit steps each, or internalTimeStep), up to frame 40 (stop time "
     "1.98e-12 s); predictionErrorDisplacement and predictionErrorDamage compare with the frames so far"},
}};

inline constexpr std::array<EnumerationValue<LearnedSample>, 3> kLearnedSampleValues{{
    {PERISTEP_LEARNED_TRAINING, LearnedSample::Training},
    {PERISTEP_LEARNED_TEST, LearnedSample::Test},
    {PERISTEP_LEARNED_TRAINING_FINE, LearnedSample::TrainingFine},
}};

inline constexpr std::array<EnumerationValue<SpecimenModel>, 3> kSpecimenModelValues{{
    {PERISTEP_SPECIMEN_QUASI_STATIC, SpecimenModel::QuasiStatic},
    {PERISTEP_SPECIMEN_DYNAMIC, SpecimenModel::Dynamic},
    {PERISTEP_SPECIMEN_ELASTIC, SpecimenModel::Elastic},
}};

inline constexpr std::array<EnumerationValue<ExactSolution>, 4> kExactSolutionValues{{
    {PERISTEP_EXACT_NONE, ExactSolution::None},
    {PERISTEP_EXACT_SMOOTH, ExactSolution::Smooth},
    {PERISTEP_EXACT_COMPOSITE, ExactSolution::Composite},
    {PERISTEP_EXACT_INTERFACE_CRACK, ExactSolution::InterfaceCrack},
}};

inline constexpr std::array<EnumerationValue<SpecimenMaterial>, 3> kMaterialFieldValues{{
    {PERISTEP_MATERIAL_MAP, SpecimenMaterial::Maps},
    {PERISTEP_MATERIAL_KL_FIELD, SpecimenMaterial::KlField},
    {PERISTEP_MATERIAL_GLASS_CERAMIC, SpecimenMaterial::GlassCeramic},
}};

inline constexpr std::array<EnumerationValue<LinearSolverKind>, 4> kLinearSolverValues{{
    {PERISTEP_LINEAR_SOLVER_UMFPACK, LinearSolverKind::Umfpack},
    {PERISTEP_LINEAR_SOLVER_UMFPACK_AMD, LinearSolverKind::UmfpackAmd},
    {PERISTEP_LINEAR_SOLVER_SPARSE_LU, LinearSolverKind::SparseLu},
    {PERISTEP_LINEAR_SOLVER_BICGSTAB_ILUT, LinearSolverKind::BicgstabIlut},
}};

inline constexpr std::array<EnumerationValue<TimeIntegratorKind>, 3> kTimeIntegratorValues{{
    {PERISTEP_INTEGRATOR_CENTRAL_DIFFERENCE, TimeIntegratorKind::CentralDifference},
    {PERISTEP_INTEGRATOR_ARKODE_ERK, TimeIntegratorKind::ArkodeErk},
    {PERISTEP_INTEGRATOR_CVODE_BDF, TimeIntegratorKind::CvodeBdf},
}};

inline constexpr std::array<EnumerationValue<CovarianceKind>, 2> kCovarianceValues{{
    {PERISTEP_COVARIANCE_EXPONENTIAL, CovarianceKind::Exponential},
    {PERISTEP_COVARIANCE_GAUSSIAN, CovarianceKind::Gaussian},
}};

inline constexpr std::array<EnumerationValue<MaterialTransform>, 2> kFieldTransformValues{{
    {PERISTEP_FIELD_AFFINE, MaterialTransform::Affine},
    {PERISTEP_FIELD_LOGNORMAL, MaterialTransform::Positive},
}};

// The C++ value of an enumeration value; the variable table refuses other values when they are set, so
// an unknown one here is an internal error.
template <class Kind, std::size_t N>
Kind kindOf(const std::array<EnumerationValue<Kind>, N>& values, std::int64_t value, std::string_view what) {
  for (const EnumerationValue<Kind>& v : values)
    if (v.value == value) return v.kind;
  throw InvalidInput("unknown " + std::string(what) + " " + std::to_string(value));
}

// The <Item>s of an enumeration type: names and descriptions from the option table, in the order of values.
template <class Kind, std::size_t N>
std::vector<EnumerationItem> enumerationItems(const std::array<EnumerationValue<Kind>, N>& values,
                                              const std::array<Option<Kind>, N>& options) {
  std::vector<EnumerationItem> items;
  for (const EnumerationValue<Kind>& v : values) {
    const Option<Kind>& o = option(options, v.kind);
    items.push_back({o.name, v.value, o.description});
  }
  return items;
}

}  // namespace peristep::fmi
