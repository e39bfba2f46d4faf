#include "fmi/variables.hpp"

#include <algorithm>

#include "fmi/enumerations.hpp"
#include "peristep.h"
#include "scenes/parameter_constants.hpp"

namespace peristep::fmi {

namespace {

using C = Causality;
using V = Variability;
using I = Initial;
using T = VarType;

constexpr fmi3ValueReference kNx = PERISTEP_VR_NX, kNy = PERISTEP_VR_NY, kModes = PERISTEP_VR_NMODES,
                             kCracks = PERISTEP_VR_NCRACKS, kBoxes = PERISTEP_VR_NGRIP_BOXES;

// Images are [ny][nx]: the outer dimension is ny (FMI arrays are row-major).
std::vector<fmi3ValueReference> image() { return {kNy, kNx}; }

// Which input drives an output (component/scenes/*_runner.cpp): loadFactor the elastic scenes, the KL
// plate, the dynamic scenes 5-7 and the specimen; loadDisplacement the glass-ceramic plate (a specimen
// preset, so the specimen's outputs depend on both).
std::vector<fmi3ValueReference> onBothLoads() { return {PERISTEP_VR_LOAD_FACTOR, PERISTEP_VR_LOAD_DISPLACEMENT}; }
std::vector<fmi3ValueReference> onLoadFactor() { return {PERISTEP_VR_LOAD_FACTOR}; }
std::vector<fmi3ValueReference> onNoInput() { return {}; }  // fixed once the scene is built

std::vector<Variable> makeTable() {
  return {
      {.name = "time", .vr = PERISTEP_VR_TIME, .type = T::Float64, .causality = C::Independent,
       .variability = V::Continuous, .initial = I::Default,
       .description = "Simulation time: each communication step is one quasi-static load increment; in the dynamic "
                      "scenes (5-7, and the specimen's dynamic model) physical time, integrated over each "
                      "communication step",
       .unit = "s"},

      {.name = "nx", .vr = PERISTEP_VR_NX, .type = T::UInt64, .causality = C::StructuralParameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Points per side in x (arrays [ny][nx] are images, x varying fastest)", .start = "33",
       .min = Bound{kMinPointsPerSide}, .max = Bound{65536}},
      {.name = "ny", .vr = PERISTEP_VR_NY, .type = T::UInt64, .causality = C::StructuralParameter,
       .variability = V::Fixed, .initial = I::Exact, .description = "Points per side in y", .start = "33",
       .min = Bound{kMinPointsPerSide}, .max = Bound{65536}},
      {.name = "nModes", .vr = PERISTEP_VR_NMODES, .type = T::UInt64, .causality = C::StructuralParameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Length of xi; at least the number of random coordinates of the scene (smooth 1, composite 2)",
       .start = "1", .min = Bound{1}, .max = Bound{1024}},
      {.name = "nCracks", .vr = PERISTEP_VR_NCRACKS, .type = T::UInt64, .causality = C::StructuralParameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: number of pre-crack segments (length of crackX0, crackY0, crackX1, crackY1)",
       .start = "1", .min = Bound{1}, .max = Bound{1024}},

      {.name = "nGripBoxes", .vr = PERISTEP_VR_NGRIP_BOXES, .type = T::UInt64, .causality = C::StructuralParameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: number of grip boxes (length of the gripBox arrays)", .start = "1",
       .min = Bound{1}, .max = Bound{1024}},

      {.name = "scene", .vr = PERISTEP_VR_SCENE, .type = T::Enumeration, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact, .description = "Built-in scene",
       .declaredType = "PeriStep.Scene", .start = "1"},
      {.name = "Lx", .vr = PERISTEP_VR_LX, .type = T::Float64, .causality = C::Parameter, .variability = V::Fixed,
       .initial = I::Exact,
       .description = "Width spanned by the points, > 0: every scene's grid has its nx x ny points on [-Lx/2, "
                      "Lx/2] x [-Ly/2, Ly/2], h = Lx/(nx-1) = Ly/(ny-1), each point carrying the h x h cell around "
                      "it (the dynamic scenes' material is those cells: a plate Lx + h wide)",
       .unit = "m", .start = "1", .min = Bound{0, true}},
      {.name = "Ly", .vr = PERISTEP_VR_LY, .type = T::Float64, .causality = C::Parameter, .variability = V::Fixed,
       .initial = I::Exact, .description = "Domain height, > 0", .unit = "m", .start = "1",
       .min = Bound{0, true}},
      {.name = "deltaOverH", .vr = PERISTEP_VR_DELTA_OVER_H, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Peridynamic horizon over grid spacing, 1 <= delta/h <= 20", .start = "3",
       .min = Bound{kMinDeltaOverH}, .max = Bound{kMaxDeltaOverH}},
      {.name = "poissonRatio", .vr = PERISTEP_VR_POISSON_RATIO, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact, .description = "Poisson's ratio (plane strain), -1 < nu < 0.5",
       .start = "0.3", .min = Bound{kMinPoissonRatio, true}, .max = Bound{kMaxPoissonRatio, true}},
      {.name = "modulusContrast", .vr = PERISTEP_VR_MODULUS_CONTRAST, .type = T::Float64,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "Composite scene: Young's modulus right of x = 0 over left, > 0", .start = "2",
       .min = Bound{0, true}},
      {.name = "jitter", .vr = PERISTEP_VR_JITTER, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Random displacement of every point as a fraction of h, 0 <= jitter < 0.5", .start = "0",
       .min = Bound{0}, .max = Bound{kMaxJitter, true}},
      {.name = "seed", .vr = PERISTEP_VR_SEED, .type = T::UInt64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact, .description = "Seed of the point jitter and of the glass-ceramic microstructure; gamutBar: the "
                      "realization of the bar (0 .. 29: the 30 realizations of bench/gamut_bar)",
       .start = "1"},
      {.name = "linearSolver", .vr = PERISTEP_VR_LINEAR_SOLVER, .type = T::Enumeration, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact, .description = "Sparse solver of the elastic (u, theta) systems of Tests 1-3; the fracture scenes use their crack-zone solver (MUMPS)",
       .declaredType = "PeriStep.LinearSolver", .start = "1"},
      {.name = "xi", .vr = PERISTEP_VR_XI, .type = T::Float64, .causality = C::Parameter, .variability = V::Fixed,
       .initial = I::Exact,
       .description = "Standardized random coordinates of this sample (physical coordinate = xiScale * xi)",
       .start = "0", .dimensions = {kModes}},
      {.name = "crystalFraction", .vr = PERISTEP_VR_CRYSTAL_FRACTION, .type = T::Float64,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "Glass-ceramic scene: crystal area fraction f in [0, 1] (ellipses added until reached)",
       .start = "0.2", .min = Bound{0, false}, .max = Bound{1, false}},
      {.name = "correlationLength", .vr = PERISTEP_VR_CORRELATION_LENGTH, .type = T::Float64,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "KL plate and specimen with a KL field: correlation length l of the covariance, > 0",
       .unit = "m", .start = "0.5", .min = Bound{0, true}},
      {.name = "fieldStd", .vr = PERISTEP_VR_FIELD_STD, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "KL plate and specimen with a KL field: standard deviation s of the Gaussian field g (E = E0 "
                      "(1 + g) or E0 exp(g - s^2/2))",
       .start = "0.3", .min = Bound{0, true}},
      {.name = "covariance", .vr = PERISTEP_VR_COVARIANCE, .type = T::Enumeration, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "KL plate and specimen with a KL field: covariance kernel of g",
       .declaredType = "PeriStep.Covariance", .start = "1"},
      {.name = "fieldTransform", .vr = PERISTEP_VR_FIELD_TRANSFORM, .type = T::Enumeration,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "KL plate and specimen with a KL field: how g becomes Young's modulus",
       .declaredType = "PeriStep.FieldTransform", .start = "1"},
      {.name = "pcaRealizations", .vr = PERISTEP_VR_PCA_REALIZATIONS, .type = T::UInt64,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "Glass-ceramic: 0 = the microstructure of seed; n > 0 = the PCA field 000:(5.5) of n "
                      "realizations (seeds 1..n) with nModes standard normal coordinates",
       .start = "0"},

      {.name = "xiDistribution", .vr = PERISTEP_VR_XI_DISTRIBUTION, .type = T::Int32,
       .causality = C::CalculatedParameter, .variability = V::Fixed, .initial = I::Calculated,
       .description = "Law of each coordinate xi: 0 normal, 1 uniform, 2 unused by the scene",
       .dimensions = {kModes}},
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
                      "step solves at its current value. Dynamic scenes: scale of the loads during the step (pull "
                      "velocity 1 m/s, bending force rate f_max at 1). Specimen: the held grips' displacement (quasi-static) or "
                      "velocity (dynamic) over its value at 1. gamutBar, monotonic protocol: end stress over "
                      "the material's sigma_f (every step pulls the bar to loadFactor * sigma_f * A)",
       .start = "1"},
      {.name = "loadDisplacement", .vr = PERISTEP_VR_LOAD_DISPLACEMENT, .type = T::Float64, .causality = C::Input,
       .variability = V::Continuous, .initial = I::Default,
       .description = "Opening U_D of the glass-ceramic plate: the top collar moves by +U_D, the bottom by -U_D; "
                      "every step breaks bonds until equilibrium at its current value; the step in which the crack crosses "
                      "the plate sets terminateSimulation (000 Sec. 5 ends the test there)",
       .unit = "m", .start = "0"},

      {.name = "ux", .vr = PERISTEP_VR_UX, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated, .description = "Displacement in x of each domain point",
       .unit = "m", .dimensions = image(), .dependencies = onBothLoads()},
      {.name = "uy", .vr = PERISTEP_VR_UY, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated, .description = "Displacement in y of each domain point",
       .unit = "m", .dimensions = image(), .dependencies = onBothLoads()},
      {.name = "damage", .vr = PERISTEP_VR_DAMAGE, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Damage of each domain point, 000:(3.23): broken fraction of its material bonds; 0 where "
                      "nothing can break. Dynamic scenes: the indicator Z of 001:(104), cracked where Z > 1",
       .dimensions = image(), .dependencies = onBothLoads()},
      {.name = "youngsModulus", .vr = PERISTEP_VR_YOUNGS_MODULUS, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Young's modulus of each domain point (the material field, e.g. the microstructure)",
       .unit = "Pa", .dimensions = image(), .dependencies = onNoInput()},
      {.name = "exactMeanUx", .vr = PERISTEP_VR_EXACT_MEAN_UX, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Mean over the random coordinates of the exact ux (Tests 1-3; see hasExactMoments)",
       .unit = "m", .dimensions = image(), .dependencies = onLoadFactor()},
      {.name = "exactMeanUy", .vr = PERISTEP_VR_EXACT_MEAN_UY, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Mean over the random coordinates of the exact uy", .unit = "m", .dimensions = image(),
       .dependencies = onLoadFactor()},
      {.name = "exactStdUx", .vr = PERISTEP_VR_EXACT_STD_UX, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Standard deviation over the random coordinates of the exact ux", .unit = "m",
       .dimensions = image(), .dependencies = onLoadFactor()},
      {.name = "exactStdUy", .vr = PERISTEP_VR_EXACT_STD_UY, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Standard deviation over the random coordinates of the exact uy", .unit = "m",
       .dimensions = image(), .dependencies = onLoadFactor()},
      {.name = "hasExactMoments", .vr = PERISTEP_VR_HAS_EXACT_MOMENTS, .type = T::Int32, .causality = C::Output,
       .variability = V::Discrete, .initial = I::Calculated,
       .description = "1 when exactMean*/exactStd* hold the scene's exact moments (Tests 1-3), 0 when they are zero",
       .dependencies = onNoInput()},
      {.name = "retainedVariance", .vr = PERISTEP_VR_RETAINED_VARIANCE, .type = T::Float64,
       .causality = C::Output, .variability = V::Continuous, .initial = I::Calculated,
       .description = "Fraction of the random field's variance carried by the retained KL or PCA modes; 1 otherwise",
       .dependencies = onNoInput()},
      {.name = "reactionLeftX", .vr = PERISTEP_VR_REACTION_LEFT_X, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Specimen and glassCeramic scenes: x-force of the left grip on the specimen per "
                      "unit thickness (0 when free)",
       .unit = "N/m", .dependencies = onBothLoads()},
      {.name = "reactionLeftY", .vr = PERISTEP_VR_REACTION_LEFT_Y, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Specimen and glassCeramic scenes: y-force of the left grip on the specimen per "
                      "unit thickness (0 when free)",
       .unit = "N/m", .dependencies = onBothLoads()},
      {.name = "reactionRightX", .vr = PERISTEP_VR_REACTION_RIGHT_X, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Specimen and glassCeramic scenes: x-force of the right grip on the specimen per "
                      "unit thickness (0 when free)",
       .unit = "N/m", .dependencies = onBothLoads()},
      {.name = "reactionRightY", .vr = PERISTEP_VR_REACTION_RIGHT_Y, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Specimen and glassCeramic scenes: y-force of the right grip on the specimen per "
                      "unit thickness (0 when free)",
       .unit = "N/m", .dependencies = onBothLoads()},
      {.name = "reactionBottomX", .vr = PERISTEP_VR_REACTION_BOTTOM_X, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Specimen and glassCeramic scenes: x-force of the bottom grip on the specimen per "
                      "unit thickness (0 when free)",
       .unit = "N/m", .dependencies = onBothLoads()},
      {.name = "reactionBottomY", .vr = PERISTEP_VR_REACTION_BOTTOM_Y, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Specimen and glassCeramic scenes: y-force of the bottom grip on the specimen per "
                      "unit thickness (0 when free)",
       .unit = "N/m", .dependencies = onBothLoads()},
      {.name = "reactionTopX", .vr = PERISTEP_VR_REACTION_TOP_X, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Specimen and glassCeramic scenes: x-force of the top grip on the specimen per "
                      "unit thickness (0 when free)",
       .unit = "N/m", .dependencies = onBothLoads()},
      {.name = "reactionTopY", .vr = PERISTEP_VR_REACTION_TOP_Y, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Specimen and glassCeramic scenes: y-force of the top grip on the specimen per "
                      "unit thickness (0 when free)",
       .unit = "N/m", .dependencies = onBothLoads()},
      {.name = "gripBoxReactionX", .vr = PERISTEP_VR_GRIP_BOX_REACTION_X, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Specimen scene, dynamic model: x-force of each grip box on the specimen per unit thickness "
                      "in its held components (0 for a free box)",
       .unit = "N/m", .dimensions = {kBoxes}, .dependencies = onBothLoads()},
      {.name = "gripBoxReactionY", .vr = PERISTEP_VR_GRIP_BOX_REACTION_Y, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Specimen scene, dynamic model: y-force of each grip box on the specimen per unit thickness",
       .unit = "N/m", .dimensions = {kBoxes}, .dependencies = onBothLoads()},
      {.name = "reactionForce", .vr = PERISTEP_VR_REACTION_FORCE, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "y-force per unit thickness of the top collar on the specimen (glass-ceramic scene and "
                      "specimens of glass-ceramic material); 0 where the scene defines none",
       .unit = "N/m", .dependencies = onBothLoads()},
      {.name = "crackLength", .vr = PERISTEP_VR_CRACK_LENGTH, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Crack length grown by loading, from broken bonds (glass-ceramic) or from the advance of "
                      "the Z > 1 zone beyond each pre-crack tip (dynamic scenes); 0 otherwise",
       .unit = "m", .dependencies = onBothLoads()},
      {.name = "brokenBonds", .vr = PERISTEP_VR_BROKEN_BONDS, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Number of broken material bonds, pre-crack included; gamutBar: bonds with an element "
                      "slipping (broken, 002:(35)) in the last step; 0 where nothing can break",
       .dependencies = onBothLoads()},
      {.name = "strainEnergy", .vr = PERISTEP_VR_STRAIN_ENERGY, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Elastic energy per unit thickness, 001:(11) (dynamic scenes); 0 in the other scenes",
       .unit = "J/m", .dependencies = onLoadFactor()},
      {.name = "fractureEnergy", .vr = PERISTEP_VR_FRACTURE_ENERGY, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Fracture energy G1 L1 + G2 L2 + Gi Li per unit thickness (glass-ceramic, 000:(5.2)); "
                      "dynamic scenes: peridynamic energy of the crack zone Z > 1 (001 Sec. 6.1.1); 0 otherwise",
       .unit = "J/m", .dependencies = onBothLoads()},
      {.name = "toughnessKIC", .vr = PERISTEP_VR_TOUGHNESS_KIC, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Fracture toughness K_IC from 000:(5.2)-(5.3) (glass-ceramic scene and specimens of "
                      "glass-ceramic material); 0 otherwise",
       .unit = "Pa.m^0.5", .dependencies = onBothLoads()},
      {.name = "errorL2", .vr = PERISTEP_VR_ERROR_L2, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "L2 error of the displacement against the scene's exact solution; 0 without one",
       .unit = "m", .dependencies = onLoadFactor()},
      {.name = "kineticEnergy", .vr = PERISTEP_VR_KINETIC_ENERGY, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Kinetic energy per unit thickness (dynamic scenes); 0 otherwise", .unit = "J/m",
       .dependencies = onLoadFactor()},
      {.name = "externalWork", .vr = PERISTEP_VR_EXTERNAL_WORK, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Work per unit thickness of the loads since the start (dynamic scenes): kineticEnergy + "
                      "strainEnergy - externalWork stays at its initial value",
       .unit = "J/m", .dependencies = onLoadFactor()},
      {.name = "forceEvaluations", .vr = PERISTEP_VR_FORCE_EVALUATIONS, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Force evaluations (and Jacobian products) the time integrator has spent since the start of the "
                      "run; an FMU state restores the count it was taken with", .dependencies = onLoadFactor()},
      {.name = "timeIntegrator", .vr = PERISTEP_VR_TIME_INTEGRATOR, .type = T::Enumeration,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "Dynamic scenes: time integrator; fmi3DoStep takes as many internal steps as it needs",
       .declaredType = "PeriStep.TimeIntegrator", .start = "1"},
      {.name = "internalTimeStep", .vr = PERISTEP_VR_INTERNAL_TIME_STEP, .type = T::Float64,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "Dynamic scenes, central difference: the internal step, refused above the stability limit; "
                      "0: the scene's step of 001 (0.004 us Plexiglass, 0.0035 us bending)",
       .unit = "s", .start = "0", .min = Bound{0}},
      {.name = "integratorTolerance", .vr = PERISTEP_VR_INTEGRATOR_TOLERANCE, .type = T::Float64,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "Dynamic scenes, SUNDIALS integrators: relative tolerance of the local error", .start = "1e-06",
       .min = Bound{0, true}, .max = Bound{1}},

      // Bounds on the work one call may start: a set-up or step estimated beyond them is refused at once
      // with the estimate and what to change (scenes/scene_cost.hpp, dynamic_runner.cpp).
      {.name = "memoryBudget", .vr = PERISTEP_VR_MEMORY_BUDGET, .type = T::UInt64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Largest estimated memory in bytes of the scene set-up (grid, bonds, assembly, "
                      "factorization, PCA, KL modes); a larger set-up is refused in initialization with the "
                      "estimate. 0: three quarters of the machine's physical memory or of the process's "
                      "address-space limit, whichever is smaller",
       .start = "0", .min = Bound{0}},
      {.name = "setUpTimeLimit", .vr = PERISTEP_VR_SET_UP_TIME_LIMIT, .type = T::Float64,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "Largest estimated run time of the scene set-up (initialization, or the first step after "
                      "a parameter change); a longer one is refused with the estimate. 0: no limit",
       .unit = "s", .start = "60", .min = Bound{0}},
      {.name = "maxInternalSteps", .vr = PERISTEP_VR_MAX_INTERNAL_STEPS, .type = T::UInt64,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "Dynamic scenes: most internal time steps one fmi3DoStep may take; central difference "
                      "refuses a longer step up front, the SUNDIALS integrators stop there. 0: no limit",
       .start = "1000000", .min = Bound{0}},

      // The specimen scene: the importer's plate on the vertex grid of the other quasi-static scenes.
      {.name = "materialYoungsModulus", .vr = PERISTEP_VR_MATERIAL_YOUNGS_MODULUS, .type = T::Float64,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: Young's modulus of each domain point; 0 = Void (no material: a hole or a "
                      "cut-out edge)",
       .unit = "Pa", .start = "80e9", .dimensions = image(), .min = Bound{0}},
      {.name = "materialField", .vr = PERISTEP_VR_MATERIAL_FIELD, .type = T::Enumeration,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: materialYoungsModulus as given, or times a Karhunen-Loeve random factor of "
                      "mean 1 drawn from xi (nModes coordinates) as in the KL plate, or the glass-ceramic of scene "
                      "glassCeramic",
       .declaredType = "PeriStep.MaterialField", .start = "1"},
      {.name = "exactSolution", .vr = PERISTEP_VR_EXACT_SOLUTION, .type = T::Enumeration,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, elastic model with every side held: the material, body force and collar "
                      "displacement (times loadFactor) of a manufactured solution of 000 Sec. 4 in place of the "
                      "maps and grips, with errorL2 and the exact moments against it (scenes smooth, composite "
                      "and interfaceCrack are these presets)",
       .declaredType = "PeriStep.ExactSolution", .start = "1"},
      {.name = "materialPoissonRatio", .vr = PERISTEP_VR_MATERIAL_POISSON_RATIO, .type = T::Float64,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: Poisson's ratio (plane strain) of each domain point, -1 < nu < 0.5",
       .start = "0.25", .dimensions = image(), .min = Bound{kMinPoissonRatio, true},
       .max = Bound{kMaxPoissonRatio, true}},
      {.name = "materialFractureEnergy", .vr = PERISTEP_VR_MATERIAL_FRACTURE_ENERGY, .type = T::Float64,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: fracture energy G of each domain point, > 0 (a bond breaks at the critical "
                      "stretch of the mean G of its ends, 000:(2.26))",
       .unit = "J/m2", .start = "6.59", .dimensions = image(), .min = Bound{0, true}},
      {.name = "materialDensity", .vr = PERISTEP_VR_MATERIAL_DENSITY, .type = T::Float64,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, dynamic model: density of each domain point, > 0 (the start value is 001 "
                      "Table 1's)",
       .unit = "kg/m3", .start = "1200", .dimensions = image(), .min = Bound{0, true}},
      {.name = "crackX0", .vr = PERISTEP_VR_CRACK_X0, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: x of the first end of each pre-crack segment (any angle, inside the plate); "
                      "bonds crossing a segment are broken from the start, a segment of length 0 is none",
       .unit = "m", .start = "0", .dimensions = {kCracks}},
      {.name = "crackY0", .vr = PERISTEP_VR_CRACK_Y0, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: y of the first end of each pre-crack segment",
       .unit = "m", .start = "0", .dimensions = {kCracks}},
      {.name = "crackX1", .vr = PERISTEP_VR_CRACK_X1, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: x of the second end of each pre-crack segment",
       .unit = "m", .start = "0", .dimensions = {kCracks}},
      {.name = "crackY1", .vr = PERISTEP_VR_CRACK_Y1, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: y of the second end of each pre-crack segment",
       .unit = "m", .start = "0", .dimensions = {kCracks}},
      {.name = "gripLeft", .vr = PERISTEP_VR_GRIP_LEFT, .type = T::Enumeration, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: the left side (x = -Lx/2), free or held by its collar (the collar's "
                      "corners go with bottom and top); the dynamic model may hold one component (heldX, heldY)",
       .declaredType = "PeriStep.Grip", .start = "1"},
      {.name = "gripRight", .vr = PERISTEP_VR_GRIP_RIGHT, .type = T::Enumeration, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: the right side (x = Lx/2), free or held by its collar (the collar's "
                      "corners go with bottom and top); the dynamic model may hold one component (heldX, heldY)",
       .declaredType = "PeriStep.Grip", .start = "1"},
      {.name = "gripBottom", .vr = PERISTEP_VR_GRIP_BOTTOM, .type = T::Enumeration, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: the bottom side (y = -Ly/2), free or held by its collar (the collar's "
                      "corners go with bottom and top); the dynamic model may hold one component (heldX, heldY)",
       .declaredType = "PeriStep.Grip", .start = "2"},
      {.name = "gripTop", .vr = PERISTEP_VR_GRIP_TOP, .type = T::Enumeration, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: the top side (y = Ly/2), free or held by its collar (the collar's "
                      "corners go with bottom and top); the dynamic model may hold one component (heldX, heldY)",
       .declaredType = "PeriStep.Grip", .start = "2"},
      {.name = "gripLeftUx", .vr = PERISTEP_VR_GRIP_LEFT_UX, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: x-displacement of the held left grip at loadFactor 1 (every step "
                      "moves it to loadFactor times this)",
       .unit = "m", .start = "0"},
      {.name = "gripLeftUy", .vr = PERISTEP_VR_GRIP_LEFT_UY, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: y-displacement of the held left grip at loadFactor 1 (every step "
                      "moves it to loadFactor times this)",
       .unit = "m", .start = "0"},
      {.name = "gripRightUx", .vr = PERISTEP_VR_GRIP_RIGHT_UX, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: x-displacement of the held right grip at loadFactor 1 (every step "
                      "moves it to loadFactor times this)",
       .unit = "m", .start = "0"},
      {.name = "gripRightUy", .vr = PERISTEP_VR_GRIP_RIGHT_UY, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: y-displacement of the held right grip at loadFactor 1 (every step "
                      "moves it to loadFactor times this)",
       .unit = "m", .start = "0"},
      {.name = "gripBottomUx", .vr = PERISTEP_VR_GRIP_BOTTOM_UX, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: x-displacement of the held bottom grip at loadFactor 1 (every step "
                      "moves it to loadFactor times this)",
       .unit = "m", .start = "0"},
      {.name = "gripBottomUy", .vr = PERISTEP_VR_GRIP_BOTTOM_UY, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: y-displacement of the held bottom grip at loadFactor 1 (every step "
                      "moves it to loadFactor times this)",
       .unit = "m", .start = "0"},
      {.name = "gripTopUx", .vr = PERISTEP_VR_GRIP_TOP_UX, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: x-displacement of the held top grip at loadFactor 1 (every step "
                      "moves it to loadFactor times this)",
       .unit = "m", .start = "0"},
      {.name = "gripTopUy", .vr = PERISTEP_VR_GRIP_TOP_UY, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: y-displacement of the held top grip at loadFactor 1 (every step "
                      "moves it to loadFactor times this)",
       .unit = "m", .start = "1e-6"},
      {.name = "specimenModel", .vr = PERISTEP_VR_SPECIMEN_MODEL, .type = T::Enumeration,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: quasi-static LPS fracture (000) or the dynamic state-based model (001)",
       .declaredType = "PeriStep.SpecimenModel", .start = "1"},
      {.name = "gripLeftVx", .vr = PERISTEP_VR_GRIP_LEFT_VX, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, dynamic model: x-velocity of the held left grip at loadFactor 1 (each "
                      "step moves it at loadFactor times this)",
       .unit = "m/s", .start = "0"},
      {.name = "gripLeftVy", .vr = PERISTEP_VR_GRIP_LEFT_VY, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, dynamic model: y-velocity of the held left grip at loadFactor 1 (each "
                      "step moves it at loadFactor times this)",
       .unit = "m/s", .start = "0"},
      {.name = "gripRightVx", .vr = PERISTEP_VR_GRIP_RIGHT_VX, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, dynamic model: x-velocity of the held right grip at loadFactor 1 (each "
                      "step moves it at loadFactor times this)",
       .unit = "m/s", .start = "0"},
      {.name = "gripRightVy", .vr = PERISTEP_VR_GRIP_RIGHT_VY, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, dynamic model: y-velocity of the held right grip at loadFactor 1 (each "
                      "step moves it at loadFactor times this)",
       .unit = "m/s", .start = "0"},
      {.name = "gripBottomVx", .vr = PERISTEP_VR_GRIP_BOTTOM_VX, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, dynamic model: x-velocity of the held bottom grip at loadFactor 1 (each "
                      "step moves it at loadFactor times this)",
       .unit = "m/s", .start = "0"},
      {.name = "gripBottomVy", .vr = PERISTEP_VR_GRIP_BOTTOM_VY, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, dynamic model: y-velocity of the held bottom grip at loadFactor 1 (each "
                      "step moves it at loadFactor times this)",
       .unit = "m/s", .start = "0"},
      {.name = "gripTopVx", .vr = PERISTEP_VR_GRIP_TOP_VX, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, dynamic model: x-velocity of the held top grip at loadFactor 1 (each "
                      "step moves it at loadFactor times this)",
       .unit = "m/s", .start = "0"},
      {.name = "gripTopVy", .vr = PERISTEP_VR_GRIP_TOP_VY, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, dynamic model: y-velocity of the held top grip at loadFactor 1 (each "
                      "step moves it at loadFactor times this)",
       .unit = "m/s", .start = "0"},
      {.name = "collarDuxDx", .vr = PERISTEP_VR_COLLAR_DUX_DX, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, quasi-static models: du_x/dx of every held collar at loadFactor 1 (a collar "
                      "point at (x, y) moves by loadFactor * (gripUx + collarDuxDx x + collarDuxDy y, gripUy + "
                      "collarDuyDx x + collarDuyDy y))",
       .start = "0"},
      {.name = "collarDuxDy", .vr = PERISTEP_VR_COLLAR_DUX_DY, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, quasi-static models: du_x/dy of every held collar at loadFactor 1 (a collar "
                      "point at (x, y) moves by loadFactor * (gripUx + collarDuxDx x + collarDuxDy y, gripUy + "
                      "collarDuyDx x + collarDuyDy y))",
       .start = "0"},
      {.name = "collarDuyDx", .vr = PERISTEP_VR_COLLAR_DUY_DX, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, quasi-static models: du_y/dx of every held collar at loadFactor 1 (a collar "
                      "point at (x, y) moves by loadFactor * (gripUx + collarDuxDx x + collarDuxDy y, gripUy + "
                      "collarDuyDx x + collarDuyDy y))",
       .start = "0"},
      {.name = "collarDuyDy", .vr = PERISTEP_VR_COLLAR_DUY_DY, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, quasi-static models: du_y/dy of every held collar at loadFactor 1 (a collar "
                      "point at (x, y) moves by loadFactor * (gripUx + collarDuxDx x + collarDuxDy y, gripUy + "
                      "collarDuyDx x + collarDuyDy y))",
       .start = "0"},
      {.name = "gripBoxX0", .vr = PERISTEP_VR_GRIP_BOX_X0, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, dynamic model: left edge of each grip box [x0, x1] x [y0, y1], a closed rectangle "
                      "whose points (domain or collar, beside a free side too) move at loadFactor * (gripBoxVx, "
                      "gripBoxVy) in the components gripBoxHold names; a point in several boxes goes with the first",
       .unit = "m", .start = "0", .dimensions = {kBoxes}},
      {.name = "gripBoxY0", .vr = PERISTEP_VR_GRIP_BOX_Y0, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, dynamic model: bottom edge of each grip box",
       .unit = "m", .start = "0", .dimensions = {kBoxes}},
      {.name = "gripBoxX1", .vr = PERISTEP_VR_GRIP_BOX_X1, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, dynamic model: right edge of each grip box, >= gripBoxX0",
       .unit = "m", .start = "0", .dimensions = {kBoxes}},
      {.name = "gripBoxY1", .vr = PERISTEP_VR_GRIP_BOX_Y1, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, dynamic model: top edge of each grip box, >= gripBoxY0",
       .unit = "m", .start = "0", .dimensions = {kBoxes}},
      {.name = "gripBoxHold", .vr = PERISTEP_VR_GRIP_BOX_HOLD, .type = T::Enumeration, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, dynamic model: what each grip box holds (free: the box is none; held, heldX, "
                      "heldY: both components or one)",
       .declaredType = "PeriStep.Grip", .start = "1", .dimensions = {kBoxes}},
      {.name = "gripBoxVx", .vr = PERISTEP_VR_GRIP_BOX_VX, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, dynamic model: x-velocity of each grip box's points at loadFactor 1",
       .unit = "m/s", .start = "0", .dimensions = {kBoxes}},
      {.name = "gripBoxVy", .vr = PERISTEP_VR_GRIP_BOX_VY, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, dynamic model: y-velocity of each grip box's points at loadFactor 1",
       .unit = "m/s", .start = "0", .dimensions = {kBoxes}},
      {.name = "bodyForceRateX", .vr = PERISTEP_VR_BODY_FORCE_RATE_X, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, dynamic model: growth rate of the x body force on each domain point, "
                      "b_x = loadFactor * t * bodyForceRateX (t: time since the run began)",
       .unit = "N/(m3.s)", .start = "0", .dimensions = image()},
      {.name = "bodyForceRateY", .vr = PERISTEP_VR_BODY_FORCE_RATE_Y, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, dynamic model: growth rate of the y body force on each domain point, "
                      "b_y = loadFactor * t * bodyForceRateY",
       .unit = "N/(m3.s)", .start = "0", .dimensions = image()},

      // The papers' material constants; a scene reads only its own.
      {.name = "glassYoungsModulus", .vr = PERISTEP_VR_GLASS_YOUNGS_MODULUS, .type = T::Float64,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "Glass-ceramic scene: Young's modulus E1 of the glass phase (000 Table 1), > 0", .unit = "Pa",
       .start = "80e9", .min = Bound{0, true}},
      {.name = "crystalYoungsModulus", .vr = PERISTEP_VR_CRYSTAL_YOUNGS_MODULUS, .type = T::Float64,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "Glass-ceramic scene: Young's modulus E2 of the crystal phase (000 Table 1), > 0", .unit = "Pa",
       .start = "133e9", .min = Bound{0, true}},
      {.name = "glassFractureEnergy", .vr = PERISTEP_VR_GLASS_FRACTURE_ENERGY, .type = T::Float64,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "Glass-ceramic scene: fracture energy G1 of the glass phase (000 Table 1), > 0",
       .unit = "J/m2", .start = "6.59", .min = Bound{0, true}},
      {.name = "crystalFractureEnergy", .vr = PERISTEP_VR_CRYSTAL_FRACTURE_ENERGY, .type = T::Float64,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "Glass-ceramic scene: fracture energy G2 of the crystal phase (000 Table 1), > 0",
       .unit = "J/m2", .start = "86.35", .min = Bound{0, true}},
      {.name = "bulkModulus", .vr = PERISTEP_VR_BULK_MODULUS, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Dynamic scenes: bulk modulus K (001 Table 1), > 0; with poissonRatio it gives the Lame "
                      "constants and E = 3 K (1 - 2 nu)",
       .unit = "Pa", .start = "25e9", .min = Bound{0, true}},
      {.name = "criticalEnergyReleaseRate", .vr = PERISTEP_VR_CRITICAL_ENERGY_RELEASE_RATE, .type = T::Float64,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "Dynamic scenes: critical energy release rate G_c (001 Table 1), > 0", .unit = "J/m2",
       .start = "500", .min = Bound{0, true}},
      {.name = "density", .vr = PERISTEP_VR_DENSITY, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Dynamic scenes: mass density rho (001 Sec. 6), > 0", .unit = "kg/m3", .start = "1200",
       .min = Bound{0, true}},

      // The 1D deformation-gamut bar of 002 (scene gamutBar); seed picks its realization.
      {.name = "gamutMaterial", .vr = PERISTEP_VR_GAMUT_MATERIAL, .type = T::Enumeration,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "gamutBar scene: the Ramberg-Osgood material of 002 Sec. 4.2",
       .declaredType = "PeriStep.GamutMaterial", .start = "1"},
      {.name = "gamutGrid", .vr = PERISTEP_VR_GAMUT_GRID, .type = T::Enumeration, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact, .description = "gamutBar scene: the grid of the bar's points",
       .declaredType = "PeriStep.GamutGrid", .start = "1"},
      {.name = "gamutBonds", .vr = PERISTEP_VR_GAMUT_BONDS, .type = T::UInt64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "gamutBar scene: local bonds of the bar (bonds + 1 points, every pair interacting), >= 4",
       .start = "500", .min = Bound{4}, .max = Bound{20000}},
      {.name = "scatterDenominator", .vr = PERISTEP_VR_SCATTER_DENOMINATOR, .type = T::Float64,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "gamutBar scene: the denominator of 002:(26), M = Mbar (1 + sign W / denominator), W "
                      "Weibull(1, weibullShape) per point and bond; 10: an RMS scatter of 10% at shape 2, > 0",
       .start = "10", .min = Bound{0, true}},
      {.name = "weibullShape", .vr = PERISTEP_VR_WEIBULL_SHAPE, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "gamutBar scene: shape of the Weibull draw W of 002:(26) (scale 1), > 0", .start = "2",
       .min = Bound{0, true}},
      {.name = "gamutProtocol", .vr = PERISTEP_VR_GAMUT_PROTOCOL, .type = T::Enumeration,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "gamutBar scene: how the bar is loaded", .declaredType = "PeriStep.GamutProtocol",
       .start = "1"},
      {.name = "barStress", .vr = PERISTEP_VR_BAR_STRESS, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "gamutBar scene: end force over area F / A after the last step; 0 otherwise", .unit = "Pa",
       .dependencies = onLoadFactor()},
      {.name = "barStrain", .vr = PERISTEP_VR_BAR_STRAIN, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "gamutBar scene: end displacement over length u(L) / L after the last step; 0 otherwise",
       .dependencies = onLoadFactor()},
      {.name = "cyclicExponent", .vr = PERISTEP_VR_CYCLIC_EXPONENT, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "gamutBar scene, cyclic protocol: n' of sigma_a = K' eps_pa^n' fitted to the stable loops "
                      "(002 Sec. 4.4.3) once the protocol's last step is done; 0 before that, in monotonic "
                      "loading and in the other scenes",
       .dependencies = onNoInput()},
      {.name = "cyclicCoefficient", .vr = PERISTEP_VR_CYCLIC_COEFFICIENT, .type = T::Float64,
       .causality = C::Output, .variability = V::Continuous, .initial = I::Calculated,
       .description = "gamutBar scene, cyclic protocol: K' of the same fit once the protocol's last step is done; 0 "
                      "before that, in monotonic loading and in the other scenes",
       .unit = "Pa", .dependencies = onNoInput()},
      {.name = "learnedSample", .vr = PERISTEP_VR_LEARNED_SAMPLE, .type = T::Enumeration, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "learnedFracture scene: the MD fracture sample predicted", .declaredType = "PeriStep.LearnedSample",
       .start = "1"},
      {.name = "learnedCriticalStretch", .vr = PERISTEP_VR_LEARNED_CRITICAL_STRETCH, .type = T::Float64,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "learnedFracture scene: critical stretch s0 of the smooth bond states 003:(28) at h = 5 A "
                      "(the fine sample takes s0 sqrt(5/3.17), 003 Sec. 5.4); 0: the s0 learned with the model "
                      "(frames 5-20 of sample III); 003's value 0.11",
       .start = "0", .min = Bound{0}},
      {.name = "predictionErrorDisplacement", .vr = PERISTEP_VR_PREDICTION_ERROR_U, .type = T::Float64,
       .causality = C::Output, .variability = V::Continuous, .initial = I::Calculated,
       .description = "learnedFracture scene: sqrt(sum_f |u_pred - u_MD|^2 / sum_f |u_MD|^2) over the frames "
                      "predicted so far and all points (003 Sec. 5.1); 0 before the first frame and in the other "
                      "scenes",
       .dependencies = onNoInput()},
      {.name = "predictionErrorDamage", .vr = PERISTEP_VR_PREDICTION_ERROR_DAMAGE, .type = T::Float64,
       .causality = C::Output, .variability = V::Continuous, .initial = I::Calculated,
       .description = "learnedFracture scene: the same for the damage 003:(46), the MD frames' own with the same "
                      "s0 and slit; 0 before the first frame and in the other scenes",
       .dependencies = onNoInput()},
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
      {"PeriStep.Scene", "Built-in scenes", enumerationItems(kSceneValues, kSceneOptions)},
      {"PeriStep.MaterialField",
       "Where the specimen's material comes from",
       {{"map", PERISTEP_MATERIAL_MAP, "The map as given"},
        {"klField", PERISTEP_MATERIAL_KL_FIELD,
         "The map times E0 (1 + g) or E0 exp(g - var/2) with E0 = 1, g the KL field of xi (fieldTransform)"},
        {"glassCeramic", PERISTEP_MATERIAL_GLASS_CERAMIC,
         "The glass-ceramic of scene glassCeramic on every point, collar included: crystals at crystalFraction "
         "placed from seed, or the PCA field of pcaRealizations microstructures at xi; the phases' "
         "glass/crystal Young's modulus and fracture energy, poissonRatio; materialYoungsModulus marks Void "
         "only. Quasi-static model; crackLength, toughnessKIC, fractureEnergy and reactionForce are measured "
         "as in glassCeramic, from the end (crackX1, crackY1) of pre-crack 0 towards +x"}}},
      {"PeriStep.GamutMaterial",
       "Ramberg-Osgood materials of paper 002 Sec. 4.2",
       {{"material1", PERISTEP_GAMUT_MATERIAL_1, "Material 1: E 71.6 GPa, sigma_y 538.6 MPa, sigma_f 665.8 MPa"},
        {"material2", PERISTEP_GAMUT_MATERIAL_2, "Material 2: E 115.7 GPa, sigma_y 867 MPa, sigma_f 933 MPa"}}},
      {"PeriStep.GamutGrid",
       "Grids of the gamutBar scene",
       {{"uniform", PERISTEP_GAMUT_GRID_UNIFORM, "Equally spaced points"},
        {"stochastic", PERISTEP_GAMUT_GRID_STOCHASTIC, "The stochastic grid of 002:(36)"}}},
      {"PeriStep.GamutProtocol",
       "Loading of the gamutBar scene",
       {{"monotonic", PERISTEP_GAMUT_MONOTONIC, "Every step moves the end stress to loadFactor * sigma_f"},
        {"cyclic", PERISTEP_GAMUT_CYCLIC,
         "Fully reversed stress-controlled cycles at 6 amplitudes from sigma_y to sigma_f, 4 steps per half "
         "cycle (53 steps, the input unused); then n' and K'"}}},
      {"PeriStep.LearnedSample",
       "MD fracture samples of paper 003 Sec. 5 (scripts/md/generate.py)",
       {{"training", PERISTEP_LEARNED_TRAINING,
         "Sample III, h = 5 A (nx = ny = 20): pre-stretched sheet with a slit, vertical edges pulled; the edge "
         "layers one horizon wide follow the frames"},
        {"test", PERISTEP_LEARNED_TEST, "Sample IV, h = 5 A (nx = ny = 20): free edges, the body-force pulse"},
        {"trainingFine", PERISTEP_LEARNED_TRAINING_FINE,
         "Sample III on h = 3.17 A (nx = ny = 31), horizon 4 h, s0 scaled by sqrt(5/3.17)"}}},
      {"PeriStep.ExactSolution", "Manufactured solutions a specimen can take",
       enumerationItems(kExactSolutionValues, kExactSolutionOptions)},
      {"PeriStep.SpecimenModel", "Models of the specimen scene",
       enumerationItems(kSpecimenModelValues, kSpecimenModelOptions)},
      {"PeriStep.Grip",
       "How a side or a grip box of the specimen is held",
       {{"free", PERISTEP_GRIP_FREE, "Traction-free: no collar beside the side"},
        {"held", PERISTEP_GRIP_HELD,
         "The collar beside the side moves rigidly: by loadFactor * (gripUx, gripUy), or at loadFactor * (gripVx, "
         "gripVy) in the dynamic model"},
        {"heldX", PERISTEP_GRIP_HELD_X, "Dynamic model: held in x only (at loadFactor * gripVx), free in y"},
        {"heldY", PERISTEP_GRIP_HELD_Y, "Dynamic model: held in y only (at loadFactor * gripVy), free in x"}}},
      {"PeriStep.LinearSolver", "Sparse solvers of the (u, theta) system",
       enumerationItems(kLinearSolverValues, kLinearSolverOptions)},
      {"PeriStep.Covariance", "Covariance kernels of the KL field",
       enumerationItems(kCovarianceValues, kCovarianceOptions)},
      {"PeriStep.FieldTransform", "How the Gaussian field g becomes Young's modulus",
       enumerationItems(kFieldTransformValues, kMaterialTransformOptions)},
      {"PeriStep.TimeIntegrator", "Time integrators of the dynamic scenes",
       enumerationItems(kTimeIntegratorValues, kTimeIntegratorOptions)},
  };
  return types;
}

const EnumerationType* findEnumeration(std::string_view name) {
  const auto& t = enumerationTypes();
  const auto it = std::find_if(t.begin(), t.end(), [name](const EnumerationType& e) { return e.name == name; });
  return it == t.end() ? nullptr : &*it;
}

const std::vector<UnitDefinition>& unitDefinitions() {
  // N/m = kg s^-2 and J/m = kg m s^-2 (per unit thickness of the plane-strain body), J/m2 = kg s^-2 (energy
  // per crack area); K_IC's Pa m^(1/2) = kg m^(-1/2) s^-2 has no integer powers.
  static const std::vector<UnitDefinition> units{
      {.name = "s", .s = 1}, {.name = "m", .m = 1}, {.name = "m/s", .m = 1, .s = -1}, {.name = "N/m", .kg = 1, .s = -2},
      {.name = "Pa", .kg = 1, .m = -1, .s = -2},
      {.name = "J/m", .kg = 1, .m = 1, .s = -2}, {.name = "J/m2", .kg = 1, .s = -2},
      {.name = "kg/m3", .kg = 1, .m = -3}, {.name = "N/(m3.s)", .kg = 1, .m = -2, .s = -3},
      {.name = "Pa.m^0.5", .integerPowers = false}};
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

std::string_view variabilityName(Variability v) {
  switch (v) {
    case Variability::Fixed: return "fixed";
    case Variability::Discrete: return "discrete";
    case Variability::Continuous: return "continuous";
  }
  return "?";
}

std::string label(const Variable& v) { return std::string(v.name) + " (vr " + std::to_string(v.vr) + ")"; }

}  // namespace peristep::fmi
