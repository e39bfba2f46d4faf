#pragma once
// A built-in scene assembled from plain parameters: the one object the FMI layer drives.
// It hides every numerical detail (geometry, quadrature, model, solver) behind set-up, advance and
// read-out, and throws InvalidInput / SolverFailure with a precise message; it never terminates.
#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/progress.hpp"
#include "core/variable_declaration.hpp"
#include "geometry/point_cloud.hpp"
#include "linalg/linear_solver_kind.hpp"
#include "models/gamut_bar.hpp"
#include "random/kl_options.hpp"
#include "scenes/specimen.hpp"
#include "solvers/time_integrator_kind.hpp"

namespace peristep {

enum class SceneId : std::int64_t {
  Smooth = 1,          // 000 Sec. 4.1, Test 1: smooth manufactured solution, one random coordinate
  Composite = 2,       // 000 Sec. 4.2, Test 2: bimaterial composite, two random coordinates
  InterfaceCrack = 3,  // 000 Sec. 4.3, Test 3: crack on a bimaterial interface, two random coordinates
  GlassCeramic = 4,    // 000 Sec. 5: pre-cracked glass-ceramic plate, microstructure from `seed` or its PCA field
  PlexiglassCrack = 5,    // 001 Sec. 6.1: dynamic crack in a pre-cracked Plexiglass square
  BendingOneNotch = 6,    // 001 Sec. 6.2: dynamic three-point bending, one pre-crack
  BendingTwoNotches = 7,  // 001 Sec. 6.2: the same with two pre-cracks
  KlPlate = 8,         // plate whose Young's modulus is a Karhunen-Loeve random field (000 Sec. 2.2)
  Specimen = 9,        // the importer's plate: material maps, pre-cracks, grips (scenes/specimen.hpp)
  GamutBar = 10,       // 002: one realization of the 1D stochastic deformation-gamut bar (models/gamut_bar.hpp)
  LearnedFracture = 11,  // 003: the learned LPS model predicting an MD fracture sample (learning/md_fracture_samples.hpp)
};

// The MD fracture samples of 003 Sec. 5 the learnedFracture scene predicts (learning::kMdFractureSamples).
enum class LearnedSample : std::int32_t { Training = 0, Test = 1, TrainingFine = 2 };

// Law of a standardized coordinate; Unused: the scene ignores that entry of xi.
enum class XiDistribution : std::int32_t { Normal = 0, Uniform = 1, Unused = 2 };

// Bounds on the work an instance may start, checked against estimates before the work begins; 0: none.
struct WorkLimits {
  double memoryBytes = 0;           // estimated peak memory of the set-up (scenes/scene_cost.hpp)
  double setUpSeconds = 0;          // estimated run time of the set-up
  std::uint64_t internalSteps = 0;  // dynamic scenes: internal time steps of one advance
};

struct SceneParameters {
  SceneId scene = SceneId::Smooth;
  GridSpec grid{};                  // nx, ny, Lx, Ly, deltaOverH, jitter, seed
  double poissonRatio = 0.3;
  double modulusContrast = 2.0;     // Composite: E(right)/E(left)
  std::vector<double> xi;           // standardized random coordinates (physical = xiScale * xi)
  LinearSolverKind linearSolver = LinearSolverKind::Umfpack;
  double crystalFraction = 0.2;     // GlassCeramic: target crystal area fraction f
  // GlassCeramic: 0 = the microstructure realization of `seed`; n > 0 = the PCA field 000:(5.5) of n
  // realizations with xi.size() modes.
  std::size_t pcaRealizations = 0;
  // KlPlate: E = E0 (1 + g) or E0 exp(g - s^2/2), g the KL expansion of a field with covariance
  // s^2 k(r / l) (000 Sec. 2.2).
  CovarianceKind covariance = CovarianceKind::Exponential;
  double correlationLength = 0.5;   // l [m]
  double fieldStd = 0.3;            // s
  MaterialTransform transform = MaterialTransform::Affine;
  // Dynamic scenes (5-7): the time integrator (solvers/time_integrator.hpp), the central difference step
  // (0: the scene's step from 001) and the SUNDIALS relative tolerance.
  TimeIntegratorKind timeIntegrator = TimeIntegratorKind::CentralDifference;
  double internalTimeStep = 0;      // [s]
  double integratorTolerance = 1e-6;
  // The papers' material constants; every scene's Poisson ratio is poissonRatio.
  double glassYoungsModulus = 80e9, crystalYoungsModulus = 133e9;   // GlassCeramic: E1, E2 [Pa] (000 Table 1)
  double glassFractureEnergy = 6.59, crystalFractureEnergy = 86.35;  // GlassCeramic: G1, G2 [J/m^2]
  double bulkModulus = 25e9;               // dynamic scenes: K [Pa] (001 Table 1)
  double criticalEnergyReleaseRate = 500;  // dynamic scenes: G_c [J/m^2]
  double density = 1200;                   // dynamic scenes: rho [kg/m^3]
  SpecimenSpec specimen;                   // Specimen: material maps, pre-cracks, grips
  // GamutBar: material, grid, bonds and scatter of the bar (bar.seed is the study seed; grid.seed picks
  // the realization), and the protocol: monotonic (every step at loadFactor sigma_f) or cyclic (the
  // protocol of scenes/gamut_loading.hpp, one force step per fmi3DoStep).
  GamutBarSpec gamutBar;
  bool gamutCyclic = false;
  // LearnedFracture: the sample, s0 at h = 5 A (0: the s0 learned with the model; 003's is 0.11; the fine sample
  // scales it), and where the FMU's resources are (the model and the frames; the FMI layer sets it from
  // fmi3InstantiateCoSimulation).
  LearnedSample learnedSample = LearnedSample::Training;
  double learnedCriticalStretch = 0;
  std::string resourcePath;
  // The values of the scene's own parameters by value reference (scenes/scene_declaration.hpp), in double
  // precision; a parameter not here takes its start value.
  std::map<ValueReference, std::vector<double>> own;
  WorkLimits limits;
  ProgressHook progress;            // optional: told how far long set-ups and steps have come
};

// Scenes 5-7 and a specimen with the dynamic model integrate the equation of motion in time; the others
// are quasi-static.
bool isDynamic(const SceneParameters& p);
// The KL plate and a specimen with a random field draw a Karhunen-Loeve field from xi.
bool usesKlField(const SceneParameters& p);
// The glassCeramic scene and a specimen of glass-ceramic material generate it (scenes/glass_ceramic_material.hpp).
bool usesGlassCeramic(const SceneParameters& p);
// A built-in scene that is a specimen gets the specimen variables of its preset (scenes/glass_ceramic.hpp);
// other scenes come back unchanged.
SceneParameters withPreset(const SceneParameters& p);

// What drives a step: the manufactured scenes and Test 3 scale their boundary data by loadFactor; the
// glass-ceramic plate is opened by loadDisplacement (top collar +U_D, bottom collar -U_D).
struct SceneInputs {
  double loadFactor = 1.0;
  double loadDisplacement = 0.0;  // [m]
  // Dynamic scenes integrate over [time, time + stepSize] with loadFactor scaling their loads from
  // `time` on (stepSize 0: outputs at the current time, nothing integrated); the quasi-static scenes
  // solve at the inputs and ignore the interval.
  double time = 0.0;              // [s] communication point (FMU time)
  double stepSize = 0.0;          // [s]
};

// Number of random coordinates the scene uses, and each one's law (for the host's sampling rules):
// Test 1: xi ~ N(0, 0.1^2); Test 2: xi1, xi2 ~ N(0, 1); Test 3: xi1 ~ N(0, 1), xi2 ~ U[-1, 1] (000 Sec. 4);
// KL plate and PCA glass-ceramic: every entry of xi, standard normal; the glass-ceramic realization of a
// seed: none.
std::size_t randomCoordinates(const SceneParameters& p);
XiDistribution xiDistribution(const SceneParameters& p, std::size_t k);
// Physical coordinate over standardized one for the parametrized scenes (the PCA field's scales are
// the square roots of its variances: SceneModel::xiScales).
double xiScale(const SceneParameters& p, std::size_t k);
// The manufactured solution of Tests 1 and 2 and of a specimen that takes one (None otherwise).
ExactSolution exactSolution(const SceneParameters& p);

// Throws InvalidInput naming the offending parameter; does no work (the limits are checked by
// checkSetUpLimits in scenes/scene_cost.hpp).
void validate(const SceneParameters& p);

class SceneModel {
 public:
  // Validates, checks the estimated cost against p.limits, builds geometry and quadrature, assembles
  // and factorizes.
  explicit SceneModel(const SceneParameters& p);
  ~SceneModel();
  SceneModel(const SceneModel&) = delete;
  SceneModel& operator=(const SceneModel&) = delete;

  // Quasi-static solve at the given inputs; scenes that can break sub-iterate until no bond breaks.
  void advance(const SceneInputs& inputs);
  void advance(double loadFactor) { advance(SceneInputs{loadFactor, 0.0}); }

  // Fields on the domain points, image order [ny][nx].
  const std::vector<double>& x() const;
  const std::vector<double>& y() const;
  const std::vector<double>& ux() const;
  const std::vector<double>& uy() const;
  const std::vector<double>& damage() const;         // zero for scenes that cannot break
  const std::vector<double>& youngsModulus() const;  // material field [Pa]
  double loadFactor() const;
  // L2 error against the exact local solution (Tests 1-3 have one; 0 otherwise).
  double errorL2() const;
  // Mean and standard deviation of the exact local solution over the random coordinates at the current
  // load (Tests 1-3; computed on the first request). Empty vectors when the scene has none.
  bool hasExactMoments() const;
  std::vector<double> exactMoment(int which) const;  // 0: mean ux, 1: mean uy, 2: std ux, 3: std uy
  // physical = xiScales()[k] * xi[k]; one per entry of xi.
  std::vector<double> xiScales() const;
  // Fraction of the field's variance the retained modes carry (KL plate, PCA glass-ceramic; else 1).
  double retainedVariance() const;
  // Fracture outputs (0 for scenes that cannot break): y-force of the top collar [N/m], crack length
  // grown by loading [m], broken material bonds (pre-crack included), fracture energy
  // G1 L1 + G2 L2 + Gi Li [J/m] and toughness K_IC [Pa m^0.5] (000:(5.2)-(5.3)).
  double reactionForce() const;
  double crackLength() const;
  double brokenBonds() const;
  double fractureEnergy() const;
  double toughnessKIC() const;
  // The crack has crossed the specimen: further load steps would only break what is left of the grips'
  // ligaments, so the FMU asks the importer to stop (terminateSimulation).
  bool separated() const;
  // Specimen scene: (x, y) force of a held grip's collar on the specimen [N/m]; 0 for a free one.
  std::array<double, 2> gripReaction(Side side) const;
  // Dynamic specimen: (x, y) force of its held grip box `box` (numbered among the held ones) [N/m].
  std::array<double, 2> boxReaction(std::size_t box) const;
  // Dynamic scenes (0 otherwise), per unit thickness: elastic energy PD(u) 001:(11), kinetic energy,
  // work of the loads since the start; and the force evaluations the integrator has spent.
  double strainEnergy() const;
  double kineticEnergy() const;
  double externalWork() const;
  double forceEvaluations() const;
  // An output the scene declares as its own (scenes/scene_declaration.hpp); 0 for another scene's.
  double ownOutput(ValueReference vr) const;

  // Checkpoint of everything that changes after set-up (load, solution, bond state).
  std::vector<std::uint8_t> saveState() const;
  void restoreState(std::span<const std::uint8_t> bytes);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace peristep
