#pragma once
// One built-in scene behind a common face: SceneModel owns a Runner and keeps the fields the FMI layer
// reads. A scene's own outputs are read from its concrete runner by its declaration (scenes/scene_declaration.hpp);
// the factories of the specimen's runners, which several scenes share, are declared here.
#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "geometry/point_cloud.hpp"
#include "scenes/scene_model.hpp"
#include "scenes/specimen.hpp"

namespace peristep {

class Runner {
 public:
  virtual ~Runner() = default;
  virtual const PointCloud& cloud() const = 0;
  virtual void advance(const SceneInputs& in) = 0;
  // Fields on the domain points, image order [ny][nx].
  virtual std::vector<double> ux() const = 0;
  virtual std::vector<double> uy() const = 0;
  virtual std::vector<double> youngsModulus() const = 0;
  virtual std::vector<double> damage() const { return {}; }  // empty: the scene cannot break
  virtual double errorL2() const { return 0.0; }
  virtual double reactionForce() const { return 0.0; }
  virtual double crackLength() const { return 0.0; }
  virtual double brokenBonds() const { return 0.0; }
  virtual double fractureEnergy() const { return 0.0; }
  virtual double toughnessKIC() const { return 0.0; }
  virtual std::array<double, 2> gripReaction(Side) const { return {0.0, 0.0}; }  // specimen scene
  virtual std::array<double, 2> boxReaction(std::size_t) const { return {0.0, 0.0}; }  // its held grip boxes
  // The test is over: the crack has crossed the specimen (000 Sec. 5 ends its test there).
  virtual bool separated() const { return false; }
  // Scales of the standardized coordinates when they come from the field itself (PCA); empty: the
  // fixed parametrization xiScale(scene, k).
  virtual std::vector<double> xiScales() const { return {}; }
  virtual double retainedVariance() const { return 1.0; }
  // Dynamic scenes: energies per unit thickness [J/m] and integrator work.
  virtual double strainEnergy() const { return 0.0; }
  virtual double kineticEnergy() const { return 0.0; }
  virtual double externalWork() const { return 0.0; }
  virtual double forceEvaluations() const { return 0.0; }
  virtual std::vector<std::uint8_t> saveState() const = 0;
  virtual void restoreState(std::span<const std::uint8_t> bytes) = 0;
};

// `p` has been validated. Random coordinates enter in physical units (xiScale * xi).
std::unique_ptr<Runner> makeDynamicRunner(const SceneParameters& p);         // 001 Sec. 6 (5-7), dynamic specimen
std::unique_ptr<Runner> makeSpecimenRunner(const SceneParameters& p);        // quasi-static specimens (withPreset)
std::unique_ptr<Runner> makeElasticSpecimenRunner(const SceneParameters& p);  // elastic specimens (withPreset)
// The dynamic scenes' own checks (the preset's specimen, a lattice without jitter, integrator options);
// throws InvalidInput.
void validateDynamicScene(const SceneParameters& p);

}  // namespace peristep
