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
  Smooth = 1,     // 000 Sec. 4.1, Test 1: smooth manufactured solution, one random coordinate
  Composite = 2,  // 000 Sec. 4.2, Test 2: bimaterial composite, two random coordinates
};

enum class XiDistribution : std::int32_t { Normal = 0, Uniform = 1 };

struct SceneParameters {
  SceneId scene = SceneId::Smooth;
  GridSpec grid{};                  // nx, ny, Lx, Ly, deltaOverH, jitter, seed
  double poissonRatio = 0.3;
  double modulusContrast = 2.0;     // Composite: E(right)/E(left)
  std::vector<double> xi;           // standardized random coordinates (physical = xiScale * xi)
  std::string linearSolver = "umfpack";
};

// Number of random coordinates the scene uses, and each one's law (for the host's sampling rules):
// Test 1: xi ~ N(0, 0.1^2); Test 2: xi1, xi2 ~ N(0, 1) (000 Sec. 4).
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

  // Quasi-static solve at the given load factor (body force and collar data scale with it).
  void advance(double loadFactor);

  // Fields on the domain points, image order [ny][nx].
  const std::vector<double>& x() const;
  const std::vector<double>& y() const;
  const std::vector<double>& ux() const;
  const std::vector<double>& uy() const;
  const std::vector<double>& damage() const;  // zero for scenes that cannot break
  double loadFactor() const;
  // L2 error against the exact local solution (the manufactured scenes have one).
  double errorL2() const;

  // Checkpoint of everything that changes after set-up (the load and the solution).
  std::vector<std::uint8_t> saveState() const;
  void restoreState(std::span<const std::uint8_t> bytes);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace peristep
