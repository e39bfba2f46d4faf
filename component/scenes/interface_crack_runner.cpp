// Test 3 (000 Sec. 4.3): the crack on a bimaterial interface under the exact near-tip field.
#include <cmath>

#include "fracture/bond_state.hpp"
#include "scenes/interface_crack.hpp"
#include "scenes/scene_runner.hpp"

namespace peristep {
namespace {

class InterfaceCrackRunner final : public Runner {
 public:
  explicit InterfaceCrackRunner(const SceneParameters& p)
      : scene_(p.grid, p.poissonRatio, xiScale(p, 0) * p.xi[0], xiScale(p, 1) * p.xi[1], p.linearSolver),
        E1_(2 + std::sin(xiScale(p, 0) * p.xi[0])),
        E2_(2 + std::sin(xiScale(p, 1) * p.xi[1])) {}
  const PointCloud& cloud() const override { return scene_.solver().discretization().cloud; }
  void advance(const SceneInputs& in) override { scene_.solve(in.loadFactor); }
  std::vector<double> ux() const override { return onDomain(cloud(), scene_.solver().displacement(), 0); }
  std::vector<double> uy() const override { return onDomain(cloud(), scene_.solver().displacement(), 1); }
  std::vector<double> youngsModulus() const override {
    // Points on the interface line belong to the upper material, as in the scene.
    std::vector<double> E;
    for (std::size_t q : cloud().domain) E.push_back(cloud().y[q] > -1e-9 * cloud().h ? E1_ : E2_);
    return E;
  }
  std::vector<double> damage() const override {
    const auto& d = scene_.solver().discretization();
    return damageField(scene_.solver().bonds(), d.cloud, d.neighbours);
  }
  double errorL2() const override { return scene_.errorL2(); }
  double brokenBonds() const override {
    const auto& d = scene_.solver().discretization();
    return static_cast<double>(brokenPairs(scene_.solver().bonds(), d.cloud, d.neighbours));
  }
  std::vector<std::uint8_t> saveState() const override { return scene_.saveState(); }
  void restoreState(std::span<const std::uint8_t> b) override { scene_.restoreState(b); }

 private:
  InterfaceCrackScene scene_;
  double E1_, E2_;
};

}  // namespace

std::unique_ptr<Runner> makeInterfaceCrackRunner(const SceneParameters& p) {
  return std::make_unique<InterfaceCrackRunner>(p);
}

std::vector<double> onDomain(const PointCloud& c, const std::vector<double>& u, int component) {
  std::vector<double> v;
  v.reserve(c.domain.size());
  for (std::size_t p : c.domain) v.push_back(u[2 * p + static_cast<std::size_t>(component)]);
  return v;
}

}  // namespace peristep
