#pragma once
// A built-in scene assembled from plain parameters: the one object the FMI layer drives.
// It hides every numerical detail (geometry, quadrature, model, solver) behind set-up, advance and
// read-out, and throws InvalidInput / SolverFailure with a precise message; it never terminates.
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "geometry/point_cloud.hpp"

namespace peristep {

enum class SceneId : std::int64_t {
  Smooth = 1,          // 000 Sec. 4.1, Test 1: smooth manufactured solution, one random coordinate
  Composite = 2,       // 000 Sec. 4.2, Test 2: bimaterial composite, two random coordinates
  InterfaceCrack = 3,  // 000 Sec. 4.3, Test 3: crack on a bimaterial interface, two random coordinates
  GlassCeramic = 4,    // 000 Sec. 5: pre-cracked glass-ceramic plate, microstructure from `seed`
};

enum class XiDistribution : std::int32_t { Normal = 0, Uniform = 1 };

struct SceneParameters {
  SceneId scene = SceneId::Smooth;
  GridSpec grid{};                  // nx, ny, Lx, Ly, deltaOverH, jitter, seed
  double poissonRatio = 0.3;
  double modulusContrast = 2.0;     // Composite: E(right)/E(left)
  std::vector<double> xi;           // standardized random coordinates (physical = xiScale * xi)
  std::string linearSolver = "umfpack";
  double crystalFraction = 0.2;     // GlassCeramic: target crystal area fraction f
};

// What drives a step: the manufactured scenes and Test 3 scale their boundary data by loadFactor; the
// glass-ceramic plate is opened by loadDisplacement (top collar +U_D, bottom collar -U_D).
struct SceneInputs {
  double loadFactor = 1.0;
  double loadDisplacement = 0.0;  // [m]
};

// Number of random coordinates the scene uses, and each one's law (for the host's sampling rules):
// Test 1: xi ~ N(0, 0.1^2); Test 2: xi1, xi2 ~ N(0, 1); Test 3: xi1 ~ N(0, 1), xi2 ~ U[-1, 1] (000 Sec. 4);
// the glass-ceramic plate has none (its microstructure comes from the seed).
std::size_t sceneModes(SceneId scene);
XiDistribution xiDistribution(SceneId scene, std::size_t k);
double xiScale(SceneId scene, std::size_t k);

// Throws InvalidInput naming the offending parameter; does no work.
void validate(const SceneParameters& p);

class SceneModel {
 public:
  // Validates, builds geometry and quadrature, assembles and factorizes.
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
  // Fracture outputs (0 for scenes that cannot break): y-force of the top collar [N/m], crack length
  // grown by loading [m], broken material bonds (pre-crack included), fracture energy
  // G1 L1 + G2 L2 + Gi Li [J/m] and toughness K_IC [Pa m^0.5] (000:(5.2)-(5.3)).
  double reactionForce() const;
  double crackLength() const;
  double brokenBonds() const;
  double fractureEnergy() const;
  double toughnessKIC() const;

  // Checkpoint of everything that changes after set-up (load, solution, bond state).
  std::vector<std::uint8_t> saveState() const;
  void restoreState(std::span<const std::uint8_t> bytes);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace peristep
