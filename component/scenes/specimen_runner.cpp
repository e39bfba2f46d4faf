// The importer's specimen behind the Runner face: the plate's cloud with a collar beside each held side,
// Void where the material map is 0 (and beside free sides), the map's E (times a KL factor with a random
// field), nu, G per point, bonds crossing a pre-crack broken, and the quasi-static fracture driver moving
// the held collars by loadFactor.
#include "fracture/bond_state.hpp"
#include "models/lps_material.hpp"
#include "quadrature/optimization_weights.hpp"
#include "scenes/kl_material.hpp"
#include "scenes/scene_runner.hpp"
#include "scenes/specimen.hpp"
#include "solvers/quasi_static_fracture.hpp"

namespace peristep {
namespace {

struct Built {
  std::shared_ptr<const LpsDiscretization> disc;
  std::vector<double> E;  // per point [Pa]
  std::array<std::vector<std::uint8_t>, 4> collars;
  std::unique_ptr<QuasiStaticFracture> fracture;
  double retainedVariance = 1.0;  // of the KL modes, with a random field
};

Built build(const SceneParameters& p) {
  const SpecimenSpec& s = p.specimen;
  Built b;
  LpsDiscretization d;
  d.cloud = specimenCloud(s, p.grid);
  const PointCloud& c = d.cloud;
  d.neighbours = findNeighbours(c, c.delta);
  d.dofs = numberDofs(c, d.neighbours);
  // Weights on the full neighbourhood, Void included, as for the glass-ceramic plate: the broken-bond
  // weights of 000:(3.18) then integrate over the part of the ball outside the material.
  d.weights = optimizationWeights(c, d.neighbours, std::vector<char>(c.size(), 1));

  std::vector<double> factor(c.size(), 1.0);
  if (s.randomField) {
    const std::shared_ptr<const KlField> field = sharedKlField(c, p);
    factor = klMaterial(*field, 1.0, p);
    b.retainedVariance = field->retainedVarianceFraction();
  }
  FractureMaterial mat;
  std::vector<double> unit(2 * c.size(), 0.0);
  for (auto& m : b.collars) m.assign(c.size(), 0);
  for (std::size_t q = 0; q < c.size(); ++q) {
    const ImageSource n = imageSource(c, q);
    const double E = c.isVoid(q) ? 0.0 : s.youngsModulus[n.image] * factor[q];
    const Lame l = planeStrain(E, s.poissonRatio[n.image]);
    b.E.push_back(E);
    mat.lambda.push_back(l.lambda);
    mat.mu.push_back(l.mu);
    mat.fractureEnergy.push_back(s.fractureEnergy[n.image]);
    if (c.region[q] != Region::Dirichlet) continue;
    const auto k = static_cast<std::size_t>(n.side);
    b.collars[k][q] = 1;
    unit[2 * q] = s.grips[k].ux;
    unit[2 * q + 1] = s.grips[k].uy;
  }
  BondState bonds = makeBondState(c, d.neighbours, mat.lambda, mat.mu, mat.fractureEnergy);
  for (const Segment& crack : s.cracks)
    if (crack.x0 != crack.x1 || crack.y0 != crack.y1) breakCrossing(bonds, c, d.neighbours, crack);
  b.disc = std::make_shared<const LpsDiscretization>(std::move(d));
  b.fracture = std::make_unique<QuasiStaticFracture>(b.disc, std::move(mat), std::move(bonds), std::move(unit),
                                                     p.linearSolver);
  return b;
}

class SpecimenRunner final : public Runner {
 public:
  explicit SpecimenRunner(const SceneParameters& p) : b_(build(p)) {
    // The outputs cover every image point: the material ones are the cloud's domain, Void ones read 0.
    output_ = b_.disc->cloud;
    output_.domain.clear();
    for (std::size_t q = 0; q < output_.size(); ++q)
      if (output_.image[q] >= 0) output_.domain.push_back(q);
  }
  const PointCloud& cloud() const override { return output_; }
  void advance(const SceneInputs& in) override { b_.fracture->advance(in.loadFactor); }
  std::vector<double> ux() const override { return onImage(b_.fracture->displacement(), 2, 0); }
  std::vector<double> uy() const override { return onImage(b_.fracture->displacement(), 2, 1); }
  std::vector<double> youngsModulus() const override { return onImage(b_.E, 1, 0); }
  // 000:(3.23) on the material points; 0 on Void, where nothing can break.
  std::vector<double> damage() const override {
    const PointCloud& c = b_.disc->cloud;
    const std::vector<double> material = damageField(b_.fracture->bonds(), c, b_.disc->neighbours);
    std::vector<double> all(c.size(), 0.0);
    for (std::size_t i = 0; i < c.domain.size(); ++i) all[c.domain[i]] = material[i];
    return onImage(all, 1, 0);
  }
  double brokenBonds() const override {
    const auto& d = b_.fracture->discretization();
    return static_cast<double>(brokenPairs(b_.fracture->bonds(), d.cloud, d.neighbours));
  }
  std::array<double, 2> gripReaction(Side side) const override {
    return b_.fracture->collarForce(b_.collars[static_cast<std::size_t>(side)]);
  }
  double retainedVariance() const override { return b_.retainedVariance; }
  std::vector<std::uint8_t> saveState() const override { return b_.fracture->saveState(); }
  void restoreState(std::span<const std::uint8_t> bytes) override { b_.fracture->restoreState(bytes); }

 private:
  std::vector<double> onImage(const std::vector<double>& field, std::size_t stride, std::size_t offset) const {
    std::vector<double> v;
    v.reserve(output_.domain.size());
    for (std::size_t q : output_.domain) v.push_back(output_.isVoid(q) ? 0.0 : field[stride * q + offset]);
    return v;
  }

  Built b_;
  PointCloud output_;
};

}  // namespace

std::unique_ptr<Runner> makeSpecimenRunner(const SceneParameters& p) { return std::make_unique<SpecimenRunner>(p); }

}  // namespace peristep
