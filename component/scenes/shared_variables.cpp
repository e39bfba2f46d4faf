#include "scenes/shared_variables.hpp"

#include "scenes/enumeration_values.hpp"
#include "scenes/parameter_constants.hpp"

namespace peristep {

namespace {

using namespace declaration_names;

constexpr ValueReference kModes = shared_vr::nModes, kCracks = 4, kBoxes = 149;

std::vector<ValueReference> image() { return imageDimensions(); }

// Which input drives an output (component/scenes/*_runner.cpp): loadFactor the elastic scenes, the KL
// plate, the dynamic scenes 5-7 and the specimen; loadDisplacement the glass-ceramic plate (a specimen
// preset, so the specimen's outputs depend on both).

std::vector<Variable> makeTable() {
  return {
      {.name = "time", .vr = 0, .type = T::Float64, .causality = C::Independent,
       .variability = V::Continuous, .initial = I::Default,
       .description = "Simulation time: each communication step is one quasi-static load increment; in the dynamic "
                      "scenes (5-7, and the specimen's dynamic model) physical time, integrated over each "
                      "communication step",
       .unit = "s"},

      {.name = "nx", .vr = 1, .type = T::UInt64, .causality = C::StructuralParameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Points per side in x (arrays [ny][nx] are images, x varying fastest)", .start = "33",
       .min = Bound{kMinPointsPerSide}, .max = Bound{65536}},
      {.name = "ny", .vr = 2, .type = T::UInt64, .causality = C::StructuralParameter,
       .variability = V::Fixed, .initial = I::Exact, .description = "Points per side in y", .start = "33",
       .min = Bound{kMinPointsPerSide}, .max = Bound{65536}},
      {.name = "nModes", .vr = 3, .type = T::UInt64, .causality = C::StructuralParameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Length of xi; at least the number of random coordinates of the scene (smooth 1, composite 2)",
       .start = "1", .min = Bound{1}, .max = Bound{1024}, .cName = "NMODES"},
      {.name = "nCracks", .vr = 4, .type = T::UInt64, .causality = C::StructuralParameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: number of pre-crack segments (length of crackX0, crackY0, crackX1, crackY1)",
       .start = "1", .min = Bound{1}, .max = Bound{1024}, .cName = "NCRACKS"},

      {.name = "nGripBoxes", .vr = 149, .type = T::UInt64, .causality = C::StructuralParameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: number of grip boxes (length of the gripBox arrays)", .start = "1",
       .min = Bound{1}, .max = Bound{1024}, .cName = "NGRIP_BOXES"},

      {.name = "scene", .vr = 10, .type = T::Enumeration, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact, .description = "Built-in scene",
       .declaredType = "PeriStep.Scene", .start = "1"},
      {.name = "Lx", .vr = 11, .type = T::Float64, .causality = C::Parameter, .variability = V::Fixed,
       .initial = I::Exact,
       .description = "Width spanned by the points, > 0: every scene's grid has its nx x ny points on [-Lx/2, "
                      "Lx/2] x [-Ly/2, Ly/2], h = Lx/(nx-1) = Ly/(ny-1), each point carrying the h x h cell around "
                      "it (the dynamic scenes' material is those cells: a plate Lx + h wide)",
       .unit = "m", .start = "1", .min = Bound{0, true}},
      {.name = "Ly", .vr = 12, .type = T::Float64, .causality = C::Parameter, .variability = V::Fixed,
       .initial = I::Exact, .description = "Domain height, > 0", .unit = "m", .start = "1",
       .min = Bound{0, true}},
      {.name = "deltaOverH", .vr = 13, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Peridynamic horizon over grid spacing, 1 <= delta/h <= 20", .start = "3",
       .min = Bound{kMinDeltaOverH}, .max = Bound{kMaxDeltaOverH}},
      {.name = "poissonRatio", .vr = 14, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact, .description = "Poisson's ratio (plane strain), -1 < nu < 0.5",
       .start = "0.3", .min = Bound{kMinPoissonRatio, true}, .max = Bound{kMaxPoissonRatio, true}},
      {.name = "modulusContrast", .vr = 15, .type = T::Float64,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "Composite scene: Young's modulus right of x = 0 over left, > 0", .start = "2",
       .min = Bound{0, true}},
      {.name = "jitter", .vr = 16, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Random displacement of every point as a fraction of h, 0 <= jitter < 0.5", .start = "0",
       .min = Bound{0}, .max = Bound{kMaxJitter, true}},
      {.name = "seed", .vr = 17, .type = T::UInt64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact, .description = "Seed of the point jitter and of the glass-ceramic microstructure; gamutBar: the "
                      "realization of the bar (0 .. 29: the 30 realizations of bench/gamut_bar)",
       .start = "1"},
      {.name = "linearSolver", .vr = 18, .type = T::Enumeration, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact, .description = "Sparse solver of the elastic (u, theta) systems of Tests 1-3; the fracture scenes use their crack-zone solver (MUMPS)",
       .declaredType = "PeriStep.LinearSolver", .start = "1"},
      {.name = "xi", .vr = 19, .type = T::Float64, .causality = C::Parameter, .variability = V::Fixed,
       .initial = I::Exact,
       .description = "Standardized random coordinates of this sample (physical coordinate = xiScale * xi)",
       .start = "0", .dimensions = {kModes}},
      {.name = "crystalFraction", .vr = 24, .type = T::Float64,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "Glass-ceramic scene: crystal area fraction f in [0, 1] (ellipses added until reached)",
       .start = "0.2", .min = Bound{0, false}, .max = Bound{1, false}},
      {.name = "correlationLength", .vr = 25, .type = T::Float64,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "KL plate and specimen with a KL field: correlation length l of the covariance, > 0",
       .unit = "m", .start = "0.5", .min = Bound{0, true}},
      {.name = "fieldStd", .vr = 26, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "KL plate and specimen with a KL field: standard deviation s of the Gaussian field g (E = E0 "
                      "(1 + g) or E0 exp(g - s^2/2))",
       .start = "0.3", .min = Bound{0, true}},
      {.name = "covariance", .vr = 27, .type = T::Enumeration, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "KL plate and specimen with a KL field: covariance kernel of g",
       .declaredType = "PeriStep.Covariance", .start = "1"},
      {.name = "fieldTransform", .vr = 28, .type = T::Enumeration,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "KL plate and specimen with a KL field: how g becomes Young's modulus",
       .declaredType = "PeriStep.FieldTransform", .start = "1"},
      {.name = "pcaRealizations", .vr = 29, .type = T::UInt64,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "Glass-ceramic: 0 = the microstructure of seed; n > 0 = the PCA field 000:(5.5) of n "
                      "realizations (seeds 1..n) with nModes standard normal coordinates",
       .start = "0"},

      {.name = "xiDistribution", .vr = 20, .type = T::Int32,
       .causality = C::CalculatedParameter, .variability = V::Fixed, .initial = I::Calculated,
       .description = "Law of each coordinate xi: 0 normal, 1 uniform, 2 unused by the scene",
       .dimensions = {kModes}},
      {.name = "xiScale", .vr = 21, .type = T::Float64, .causality = C::CalculatedParameter,
       .variability = V::Fixed, .initial = I::Calculated,
       .description = "Scale of each coordinate: physical coordinate = xiScale * xi", .dimensions = {kModes}},
      {.name = "x", .vr = 22, .type = T::Float64, .causality = C::CalculatedParameter,
       .variability = V::Fixed, .initial = I::Calculated, .description = "x coordinate of each domain point",
       .unit = "m", .dimensions = image()},
      {.name = "y", .vr = 23, .type = T::Float64, .causality = C::CalculatedParameter,
       .variability = V::Fixed, .initial = I::Calculated, .description = "y coordinate of each domain point",
       .unit = "m", .dimensions = image()},

      {.name = "loadFactor", .vr = 30, .type = T::Float64, .causality = C::Input,
       .variability = V::Continuous, .initial = I::Default,
       .description = "Scale of the body force and boundary data (scenes smooth, composite, interfaceCrack); every "
                      "step solves at its current value. Dynamic scenes: scale of the loads during the step (pull "
                      "velocity 1 m/s, bending force rate f_max at 1). Specimen: the held grips' displacement (quasi-static) or "
                      "velocity (dynamic) over its value at 1. gamutBar, monotonic protocol: end stress over "
                      "the material's sigma_f (every step pulls the bar to loadFactor * sigma_f * A)",
       .start = "1"},
      {.name = "loadDisplacement", .vr = 31, .type = T::Float64, .causality = C::Input,
       .variability = V::Continuous, .initial = I::Default,
       .description = "Opening U_D of the glass-ceramic plate: the top collar moves by +U_D, the bottom by -U_D; "
                      "every step breaks bonds until equilibrium at its current value; the step in which the crack crosses "
                      "the plate sets terminateSimulation (000 Sec. 5 ends the test there)",
       .unit = "m", .start = "0"},

      {.name = "ux", .vr = 40, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated, .description = "Displacement in x of each domain point",
       .unit = "m", .dimensions = image(), .dependencies = onBothLoads()},
      {.name = "uy", .vr = 41, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated, .description = "Displacement in y of each domain point",
       .unit = "m", .dimensions = image(), .dependencies = onBothLoads()},
      {.name = "damage", .vr = 42, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Damage of each domain point, 000:(3.23): broken fraction of its material bonds; 0 where "
                      "nothing can break. Dynamic scenes: the indicator Z of 001:(104), cracked where Z > 1",
       .dimensions = image(), .dependencies = onBothLoads()},
      {.name = "youngsModulus", .vr = 43, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Young's modulus of each domain point (the material field, e.g. the microstructure)",
       .unit = "Pa", .dimensions = image(), .dependencies = onNoInput()},
      {.name = "exactMeanUx", .vr = 44, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Mean over the random coordinates of the exact ux (Tests 1-3; see hasExactMoments)",
       .unit = "m", .dimensions = image(), .dependencies = onLoadFactor()},
      {.name = "exactMeanUy", .vr = 45, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Mean over the random coordinates of the exact uy", .unit = "m", .dimensions = image(),
       .dependencies = onLoadFactor()},
      {.name = "exactStdUx", .vr = 46, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Standard deviation over the random coordinates of the exact ux", .unit = "m",
       .dimensions = image(), .dependencies = onLoadFactor()},
      {.name = "exactStdUy", .vr = 47, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Standard deviation over the random coordinates of the exact uy", .unit = "m",
       .dimensions = image(), .dependencies = onLoadFactor()},
      {.name = "hasExactMoments", .vr = 48, .type = T::Int32, .causality = C::Output,
       .variability = V::Discrete, .initial = I::Calculated,
       .description = "1 when exactMean*/exactStd* hold the scene's exact moments (Tests 1-3), 0 when they are zero",
       .dependencies = onNoInput()},
      {.name = "retainedVariance", .vr = 49, .type = T::Float64,
       .causality = C::Output, .variability = V::Continuous, .initial = I::Calculated,
       .description = "Fraction of the random field's variance carried by the retained KL or PCA modes; 1 otherwise",
       .dependencies = onNoInput()},
      {.name = "reactionLeftX", .vr = 100, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Specimen and glassCeramic scenes: x-force of the left grip on the specimen per "
                      "unit thickness (0 when free)",
       .unit = "N/m", .dependencies = onBothLoads()},
      {.name = "reactionLeftY", .vr = 101, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Specimen and glassCeramic scenes: y-force of the left grip on the specimen per "
                      "unit thickness (0 when free)",
       .unit = "N/m", .dependencies = onBothLoads()},
      {.name = "reactionRightX", .vr = 102, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Specimen and glassCeramic scenes: x-force of the right grip on the specimen per "
                      "unit thickness (0 when free)",
       .unit = "N/m", .dependencies = onBothLoads()},
      {.name = "reactionRightY", .vr = 103, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Specimen and glassCeramic scenes: y-force of the right grip on the specimen per "
                      "unit thickness (0 when free)",
       .unit = "N/m", .dependencies = onBothLoads()},
      {.name = "reactionBottomX", .vr = 104, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Specimen and glassCeramic scenes: x-force of the bottom grip on the specimen per "
                      "unit thickness (0 when free)",
       .unit = "N/m", .dependencies = onBothLoads()},
      {.name = "reactionBottomY", .vr = 105, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Specimen and glassCeramic scenes: y-force of the bottom grip on the specimen per "
                      "unit thickness (0 when free)",
       .unit = "N/m", .dependencies = onBothLoads()},
      {.name = "reactionTopX", .vr = 106, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Specimen and glassCeramic scenes: x-force of the top grip on the specimen per "
                      "unit thickness (0 when free)",
       .unit = "N/m", .dependencies = onBothLoads()},
      {.name = "reactionTopY", .vr = 107, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Specimen and glassCeramic scenes: y-force of the top grip on the specimen per "
                      "unit thickness (0 when free)",
       .unit = "N/m", .dependencies = onBothLoads()},
      {.name = "gripBoxReactionX", .vr = 159, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Specimen scene, dynamic model: x-force of each grip box on the specimen per unit thickness "
                      "in its held components (0 for a free box)",
       .unit = "N/m", .dimensions = {kBoxes}, .dependencies = onBothLoads()},
      {.name = "gripBoxReactionY", .vr = 160, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Specimen scene, dynamic model: y-force of each grip box on the specimen per unit thickness",
       .unit = "N/m", .dimensions = {kBoxes}, .dependencies = onBothLoads()},
      {.name = "reactionForce", .vr = 50, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "y-force per unit thickness of the top collar on the specimen (glass-ceramic scene and "
                      "specimens of glass-ceramic material); 0 where the scene defines none",
       .unit = "N/m", .dependencies = onBothLoads()},
      {.name = "crackLength", .vr = 51, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Crack length grown by loading, from broken bonds (glass-ceramic) or from the advance of "
                      "the Z > 1 zone beyond each pre-crack tip (dynamic scenes); 0 otherwise",
       .unit = "m", .dependencies = onBothLoads()},
      {.name = "brokenBonds", .vr = 52, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Number of broken material bonds, pre-crack included; gamutBar: bonds with an element "
                      "slipping (broken, 002:(35)) in the last step; 0 where nothing can break",
       .dependencies = onBothLoads()},
      {.name = "strainEnergy", .vr = 53, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Elastic energy per unit thickness, 001:(11) (dynamic scenes); 0 in the other scenes",
       .unit = "J/m", .dependencies = onLoadFactor()},
      {.name = "fractureEnergy", .vr = 54, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Fracture energy G1 L1 + G2 L2 + Gi Li per unit thickness (glass-ceramic, 000:(5.2)); "
                      "dynamic scenes: peridynamic energy of the crack zone Z > 1 (001 Sec. 6.1.1); 0 otherwise",
       .unit = "J/m", .dependencies = onBothLoads()},
      {.name = "toughnessKIC", .vr = 55, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Fracture toughness K_IC from 000:(5.2)-(5.3) (glass-ceramic scene and specimens of "
                      "glass-ceramic material); 0 otherwise",
       .unit = "Pa.m^0.5", .dependencies = onBothLoads()},
      {.name = "errorL2", .vr = 56, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "L2 error of the displacement against the scene's exact solution; 0 without one",
       .unit = "m", .dependencies = onLoadFactor()},
      {.name = "kineticEnergy", .vr = 57, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Kinetic energy per unit thickness (dynamic scenes); 0 otherwise", .unit = "J/m",
       .dependencies = onLoadFactor()},
      {.name = "externalWork", .vr = 58, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Work per unit thickness of the loads since the start (dynamic scenes): kineticEnergy + "
                      "strainEnergy - externalWork stays at its initial value",
       .unit = "J/m", .dependencies = onLoadFactor()},
      {.name = "forceEvaluations", .vr = 59, .type = T::Float64, .causality = C::Output,
       .variability = V::Continuous, .initial = I::Calculated,
       .description = "Force evaluations (and Jacobian products) the time integrator has spent since the start of the "
                      "run; an FMU state restores the count it was taken with", .dependencies = onLoadFactor()},
      {.name = "timeIntegrator", .vr = 60, .type = T::Enumeration,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "Dynamic scenes: time integrator; fmi3DoStep takes as many internal steps as it needs",
       .declaredType = "PeriStep.TimeIntegrator", .start = "1"},
      {.name = "internalTimeStep", .vr = 61, .type = T::Float64,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "Dynamic scenes, central difference: the internal step, refused above the stability limit; "
                      "0: the scene's step of 001 (0.004 us Plexiglass, 0.0035 us bending)",
       .unit = "s", .start = "0", .min = Bound{0}},
      {.name = "integratorTolerance", .vr = 62, .type = T::Float64,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "Dynamic scenes, SUNDIALS integrators: relative tolerance of the local error", .start = "1e-06",
       .min = Bound{0, true}, .max = Bound{1}},

      // Bounds on the work one call may start: a set-up or step estimated beyond them is refused at once
      // with the estimate and what to change (scenes/scene_cost.hpp, dynamic_runner.cpp).
      {.name = "memoryBudget", .vr = 63, .type = T::UInt64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Largest estimated memory in bytes of the scene set-up (grid, bonds, assembly, "
                      "factorization, PCA, KL modes); a larger set-up is refused in initialization with the "
                      "estimate. 0: three quarters of the machine's physical memory or of the process's "
                      "address-space limit, whichever is smaller",
       .start = "0", .min = Bound{0}},
      {.name = "setUpTimeLimit", .vr = 64, .type = T::Float64,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "Largest estimated run time of the scene set-up (initialization, or the first step after "
                      "a parameter change); a longer one is refused with the estimate. 0: no limit",
       .unit = "s", .start = "60", .min = Bound{0}},
      {.name = "maxInternalSteps", .vr = 65, .type = T::UInt64,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "Dynamic scenes: most internal time steps one fmi3DoStep may take; central difference "
                      "refuses a longer step up front, the SUNDIALS integrators stop there. 0: no limit",
       .start = "1000000", .min = Bound{0}},

      // The specimen scene: the importer's plate on the vertex grid of the other quasi-static scenes.
      {.name = "materialYoungsModulus", .vr = 80, .type = T::Float64,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: Young's modulus of each domain point; 0 = Void (no material: a hole or a "
                      "cut-out edge)",
       .unit = "Pa", .start = "80e9", .dimensions = image(), .min = Bound{0}},
      {.name = "materialField", .vr = 79, .type = T::Enumeration,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: materialYoungsModulus as given, or times a Karhunen-Loeve random factor of "
                      "mean 1 drawn from xi (nModes coordinates) as in the KL plate, or the glass-ceramic of scene "
                      "glassCeramic",
       .declaredType = "PeriStep.MaterialField", .start = "1"},
      {.name = "exactSolution", .vr = 148, .type = T::Enumeration,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, elastic model with every side held: the material, body force and collar "
                      "displacement (times loadFactor) of a manufactured solution of 000 Sec. 4 in place of the "
                      "maps and grips, with errorL2 and the exact moments against it (scenes smooth, composite "
                      "and interfaceCrack are these presets)",
       .declaredType = "PeriStep.ExactSolution", .start = "1"},
      {.name = "materialPoissonRatio", .vr = 81, .type = T::Float64,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: Poisson's ratio (plane strain) of each domain point, -1 < nu < 0.5",
       .start = "0.25", .dimensions = image(), .min = Bound{kMinPoissonRatio, true},
       .max = Bound{kMaxPoissonRatio, true}},
      {.name = "materialFractureEnergy", .vr = 82, .type = T::Float64,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: fracture energy G of each domain point, > 0 (a bond breaks at the critical "
                      "stretch of the mean G of its ends, 000:(2.26))",
       .unit = "J/m2", .start = "6.59", .dimensions = image(), .min = Bound{0, true}},
      {.name = "materialDensity", .vr = 78, .type = T::Float64,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, dynamic model: density of each domain point, > 0 (the start value is 001 "
                      "Table 1's)",
       .unit = "kg/m3", .start = "1200", .dimensions = image(), .min = Bound{0, true}},
      {.name = "crackX0", .vr = 83, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: x of the first end of each pre-crack segment (any angle, inside the plate); "
                      "bonds crossing a segment are broken from the start, a segment of length 0 is none",
       .unit = "m", .start = "0", .dimensions = {kCracks}},
      {.name = "crackY0", .vr = 84, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: y of the first end of each pre-crack segment",
       .unit = "m", .start = "0", .dimensions = {kCracks}},
      {.name = "crackX1", .vr = 85, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: x of the second end of each pre-crack segment",
       .unit = "m", .start = "0", .dimensions = {kCracks}},
      {.name = "crackY1", .vr = 86, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: y of the second end of each pre-crack segment",
       .unit = "m", .start = "0", .dimensions = {kCracks}},
      {.name = "gripLeft", .vr = 87, .type = T::Enumeration, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: the left side (x = -Lx/2), free or held by its collar (the collar's "
                      "corners go with bottom and top); the dynamic model may hold one component (heldX, heldY)",
       .declaredType = "PeriStep.Grip", .start = "1"},
      {.name = "gripRight", .vr = 88, .type = T::Enumeration, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: the right side (x = Lx/2), free or held by its collar (the collar's "
                      "corners go with bottom and top); the dynamic model may hold one component (heldX, heldY)",
       .declaredType = "PeriStep.Grip", .start = "1"},
      {.name = "gripBottom", .vr = 89, .type = T::Enumeration, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: the bottom side (y = -Ly/2), free or held by its collar (the collar's "
                      "corners go with bottom and top); the dynamic model may hold one component (heldX, heldY)",
       .declaredType = "PeriStep.Grip", .start = "2"},
      {.name = "gripTop", .vr = 90, .type = T::Enumeration, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: the top side (y = Ly/2), free or held by its collar (the collar's "
                      "corners go with bottom and top); the dynamic model may hold one component (heldX, heldY)",
       .declaredType = "PeriStep.Grip", .start = "2"},
      {.name = "gripLeftUx", .vr = 91, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: x-displacement of the held left grip at loadFactor 1 (every step "
                      "moves it to loadFactor times this)",
       .unit = "m", .start = "0"},
      {.name = "gripLeftUy", .vr = 92, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: y-displacement of the held left grip at loadFactor 1 (every step "
                      "moves it to loadFactor times this)",
       .unit = "m", .start = "0"},
      {.name = "gripRightUx", .vr = 93, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: x-displacement of the held right grip at loadFactor 1 (every step "
                      "moves it to loadFactor times this)",
       .unit = "m", .start = "0"},
      {.name = "gripRightUy", .vr = 94, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: y-displacement of the held right grip at loadFactor 1 (every step "
                      "moves it to loadFactor times this)",
       .unit = "m", .start = "0"},
      {.name = "gripBottomUx", .vr = 95, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: x-displacement of the held bottom grip at loadFactor 1 (every step "
                      "moves it to loadFactor times this)",
       .unit = "m", .start = "0"},
      {.name = "gripBottomUy", .vr = 96, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: y-displacement of the held bottom grip at loadFactor 1 (every step "
                      "moves it to loadFactor times this)",
       .unit = "m", .start = "0"},
      {.name = "gripTopUx", .vr = 97, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: x-displacement of the held top grip at loadFactor 1 (every step "
                      "moves it to loadFactor times this)",
       .unit = "m", .start = "0"},
      {.name = "gripTopUy", .vr = 98, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: y-displacement of the held top grip at loadFactor 1 (every step "
                      "moves it to loadFactor times this)",
       .unit = "m", .start = "1e-6"},
      {.name = "specimenModel", .vr = 99, .type = T::Enumeration,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene: quasi-static LPS fracture (000) or the dynamic state-based model (001)",
       .declaredType = "PeriStep.SpecimenModel", .start = "1"},
      {.name = "gripLeftVx", .vr = 130, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, dynamic model: x-velocity of the held left grip at loadFactor 1 (each "
                      "step moves it at loadFactor times this)",
       .unit = "m/s", .start = "0"},
      {.name = "gripLeftVy", .vr = 131, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, dynamic model: y-velocity of the held left grip at loadFactor 1 (each "
                      "step moves it at loadFactor times this)",
       .unit = "m/s", .start = "0"},
      {.name = "gripRightVx", .vr = 132, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, dynamic model: x-velocity of the held right grip at loadFactor 1 (each "
                      "step moves it at loadFactor times this)",
       .unit = "m/s", .start = "0"},
      {.name = "gripRightVy", .vr = 133, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, dynamic model: y-velocity of the held right grip at loadFactor 1 (each "
                      "step moves it at loadFactor times this)",
       .unit = "m/s", .start = "0"},
      {.name = "gripBottomVx", .vr = 134, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, dynamic model: x-velocity of the held bottom grip at loadFactor 1 (each "
                      "step moves it at loadFactor times this)",
       .unit = "m/s", .start = "0"},
      {.name = "gripBottomVy", .vr = 135, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, dynamic model: y-velocity of the held bottom grip at loadFactor 1 (each "
                      "step moves it at loadFactor times this)",
       .unit = "m/s", .start = "0"},
      {.name = "gripTopVx", .vr = 136, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, dynamic model: x-velocity of the held top grip at loadFactor 1 (each "
                      "step moves it at loadFactor times this)",
       .unit = "m/s", .start = "0"},
      {.name = "gripTopVy", .vr = 137, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, dynamic model: y-velocity of the held top grip at loadFactor 1 (each "
                      "step moves it at loadFactor times this)",
       .unit = "m/s", .start = "0"},
      {.name = "collarDuxDx", .vr = 144, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, quasi-static models: du_x/dx of every held collar at loadFactor 1 (a collar "
                      "point at (x, y) moves by loadFactor * (gripUx + collarDuxDx x + collarDuxDy y, gripUy + "
                      "collarDuyDx x + collarDuyDy y))",
       .start = "0"},
      {.name = "collarDuxDy", .vr = 145, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, quasi-static models: du_x/dy of every held collar at loadFactor 1 (a collar "
                      "point at (x, y) moves by loadFactor * (gripUx + collarDuxDx x + collarDuxDy y, gripUy + "
                      "collarDuyDx x + collarDuyDy y))",
       .start = "0"},
      {.name = "collarDuyDx", .vr = 146, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, quasi-static models: du_y/dx of every held collar at loadFactor 1 (a collar "
                      "point at (x, y) moves by loadFactor * (gripUx + collarDuxDx x + collarDuxDy y, gripUy + "
                      "collarDuyDx x + collarDuyDy y))",
       .start = "0"},
      {.name = "collarDuyDy", .vr = 147, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, quasi-static models: du_y/dy of every held collar at loadFactor 1 (a collar "
                      "point at (x, y) moves by loadFactor * (gripUx + collarDuxDx x + collarDuxDy y, gripUy + "
                      "collarDuyDx x + collarDuyDy y))",
       .start = "0"},
      {.name = "gripBoxX0", .vr = 150, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, dynamic model: left edge of each grip box [x0, x1] x [y0, y1], a closed rectangle "
                      "whose points (domain or collar, beside a free side too) move at loadFactor * (gripBoxVx, "
                      "gripBoxVy) in the components gripBoxHold names; a point in several boxes goes with the first",
       .unit = "m", .start = "0", .dimensions = {kBoxes}},
      {.name = "gripBoxY0", .vr = 151, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, dynamic model: bottom edge of each grip box",
       .unit = "m", .start = "0", .dimensions = {kBoxes}},
      {.name = "gripBoxX1", .vr = 152, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, dynamic model: right edge of each grip box, >= gripBoxX0",
       .unit = "m", .start = "0", .dimensions = {kBoxes}},
      {.name = "gripBoxY1", .vr = 153, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, dynamic model: top edge of each grip box, >= gripBoxY0",
       .unit = "m", .start = "0", .dimensions = {kBoxes}},
      {.name = "gripBoxHold", .vr = 154, .type = T::Enumeration, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, dynamic model: what each grip box holds (free: the box is none; held, heldX, "
                      "heldY: both components or one)",
       .declaredType = "PeriStep.Grip", .start = "1", .dimensions = {kBoxes}},
      {.name = "gripBoxVx", .vr = 155, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, dynamic model: x-velocity of each grip box's points at loadFactor 1",
       .unit = "m/s", .start = "0", .dimensions = {kBoxes}},
      {.name = "gripBoxVy", .vr = 156, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, dynamic model: y-velocity of each grip box's points at loadFactor 1",
       .unit = "m/s", .start = "0", .dimensions = {kBoxes}},
      {.name = "bodyForceRateX", .vr = 157, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, dynamic model: growth rate of the x body force on each domain point, "
                      "b_x = loadFactor * t * bodyForceRateX (t: time since the run began)",
       .unit = "N/(m3.s)", .start = "0", .dimensions = image()},
      {.name = "bodyForceRateY", .vr = 158, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Specimen scene, dynamic model: growth rate of the y body force on each domain point, "
                      "b_y = loadFactor * t * bodyForceRateY",
       .unit = "N/(m3.s)", .start = "0", .dimensions = image()},

      // The papers' material constants; a scene reads only its own.
      {.name = "glassYoungsModulus", .vr = 70, .type = T::Float64,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "Glass-ceramic scene: Young's modulus E1 of the glass phase (000 Table 1), > 0", .unit = "Pa",
       .start = "80e9", .min = Bound{0, true}},
      {.name = "crystalYoungsModulus", .vr = 71, .type = T::Float64,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "Glass-ceramic scene: Young's modulus E2 of the crystal phase (000 Table 1), > 0", .unit = "Pa",
       .start = "133e9", .min = Bound{0, true}},
      {.name = "glassFractureEnergy", .vr = 72, .type = T::Float64,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "Glass-ceramic scene: fracture energy G1 of the glass phase (000 Table 1), > 0",
       .unit = "J/m2", .start = "6.59", .min = Bound{0, true}},
      {.name = "crystalFractureEnergy", .vr = 73, .type = T::Float64,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "Glass-ceramic scene: fracture energy G2 of the crystal phase (000 Table 1), > 0",
       .unit = "J/m2", .start = "86.35", .min = Bound{0, true}},
      {.name = "bulkModulus", .vr = 74, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Dynamic scenes: bulk modulus K (001 Table 1), > 0; with poissonRatio it gives the Lame "
                      "constants and E = 3 K (1 - 2 nu)",
       .unit = "Pa", .start = "25e9", .min = Bound{0, true}},
      {.name = "criticalEnergyReleaseRate", .vr = 75, .type = T::Float64,
       .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
       .description = "Dynamic scenes: critical energy release rate G_c (001 Table 1), > 0", .unit = "J/m2",
       .start = "500", .min = Bound{0, true}},
      {.name = "density", .vr = 76, .type = T::Float64, .causality = C::Parameter,
       .variability = V::Fixed, .initial = I::Exact,
       .description = "Dynamic scenes: mass density rho (001 Sec. 6), > 0", .unit = "kg/m3", .start = "1200",
       .min = Bound{0, true}},
  };
}

}  // namespace

const std::vector<Variable>& sharedVariables() {
  static const std::vector<Variable> table = makeTable();
  return table;
}

const std::vector<EnumerationType>& sharedEnumerations() {
  static const std::vector<EnumerationType> types{
      {"PeriStep.MaterialField",
       "Where the specimen's material comes from",
       {{"map", 1, "The map as given"},
        {"klField", 2,
         "The map times E0 (1 + g) or E0 exp(g - var/2) with E0 = 1, g the KL field of xi (fieldTransform)"},
        {"glassCeramic", 3,
         "The glass-ceramic of scene glassCeramic on every point, collar included: crystals at crystalFraction "
         "placed from seed, or the PCA field of pcaRealizations microstructures at xi; the phases' "
         "glass/crystal Young's modulus and fracture energy, poissonRatio; materialYoungsModulus marks Void "
         "only. Quasi-static model; crackLength, toughnessKIC, fractureEnergy and reactionForce are measured "
         "as in glassCeramic, from the end (crackX1, crackY1) of pre-crack 0 towards +x"}},
       "PERISTEP_MATERIAL_"},
      {"PeriStep.ExactSolution", "Manufactured solutions a specimen can take",
       enumerationItems(kExactSolutionValues, kExactSolutionOptions), "PERISTEP_EXACT_"},
      {"PeriStep.SpecimenModel", "Models of the specimen scene",
       enumerationItems(kSpecimenModelValues, kSpecimenModelOptions), "PERISTEP_SPECIMEN_"},
      {"PeriStep.Grip",
       "How a side or a grip box of the specimen is held",
       {{"free", 1, "Traction-free: no collar beside the side"},
        {"held", 2,
         "The collar beside the side moves rigidly: by loadFactor * (gripUx, gripUy), or at loadFactor * (gripVx, "
         "gripVy) in the dynamic model"},
        {"heldX", 3, "Dynamic model: held in x only (at loadFactor * gripVx), free in y"},
        {"heldY", 4, "Dynamic model: held in y only (at loadFactor * gripVy), free in x"}},
       "PERISTEP_GRIP_"},
      {"PeriStep.LinearSolver", "Sparse solvers of the (u, theta) system",
       enumerationItems(kLinearSolverValues, kLinearSolverOptions), "PERISTEP_LINEAR_SOLVER_"},
      {"PeriStep.Covariance", "Covariance kernels of the KL field",
       enumerationItems(kCovarianceValues, kCovarianceOptions), "PERISTEP_COVARIANCE_"},
      {"PeriStep.FieldTransform", "How the Gaussian field g becomes Young's modulus",
       enumerationItems(kFieldTransformValues, kMaterialTransformOptions), "PERISTEP_FIELD_"},
      {"PeriStep.TimeIntegrator", "Time integrators of the dynamic scenes",
       enumerationItems(kTimeIntegratorValues, kTimeIntegratorOptions), "PERISTEP_INTEGRATOR_"},
  };
  return types;
}

const std::vector<EnumerationType>& outputEnumerations() {
  static const std::vector<EnumerationType> types{
      {"PeriStep.XiDistribution",
       "Law of a random coordinate (xiDistribution)",
       {{"normal", static_cast<std::int64_t>(XiDistribution::Normal), "Standard normal"},
        {"uniform", static_cast<std::int64_t>(XiDistribution::Uniform), "Uniform on [-1, 1]"},
        {"unused", static_cast<std::int64_t>(XiDistribution::Unused), "The scene ignores this entry"}},
       "PERISTEP_XI_"}};
  return types;
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

}  // namespace peristep
