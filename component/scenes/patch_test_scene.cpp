// Scene patchTest: the patch test of the LPS discretization (000 Sec. 3). Every side's collar follows the
// affine field u = loadFactor * (exx x + exy y, exy x + eyy y) on a homogeneous plate; a consistent
// discretization reproduces it at every point, as every family there is complete (the collar is 2 delta
// thick), so patchError measures how far the solved field is from it. This file is the whole scene: its
// parameters, its output, its runner and its declaration (the walk-through of README "Adding a scene").
#include <algorithm>
#include <cmath>

#include "core/errors.hpp"
#include "scenes/scene_declaration.hpp"
#include "scenes/scene_runner.hpp"
#include "scenes/shared_variables.hpp"

namespace peristep {
namespace {

constexpr ValueReference kStrainXX = 170, kStrainYY = 171, kStrainXY = 172, kPatchError = 173;

// The specimen the scene is: elastic, E = 1 Pa everywhere (the field does not depend on it), every side
// held still but for the collar gradient.
SpecimenSpec patchSpecimen(const SceneParameters& p) {
  SpecimenSpec s;
  s.model = SpecimenModel::Elastic;
  const std::size_t n = p.grid.nx * p.grid.ny;
  s.youngsModulus.assign(n, 1.0);
  s.poissonRatio.assign(n, p.poissonRatio);
  s.fractureEnergy.assign(n, 1.0);  // not read by the elastic model
  s.density.assign(n, 1.0);         // nor this
  for (Grip& grip : s.grips) grip.held = true;
  const double exy = ownValue(p, kStrainXY);
  s.collarGradient = {ownValue(p, kStrainXX), exy, exy, ownValue(p, kStrainYY)};
  return s;
}

class PatchTestRunner final : public Runner {
 public:
  explicit PatchTestRunner(const SceneParameters& p) {
    SceneParameters q = p;
    q.specimen = patchSpecimen(p);
    gradient_ = q.specimen.collarGradient;
    elastic_ = makeElasticSpecimenRunner(q);
  }
  const PointCloud& cloud() const override { return elastic_->cloud(); }
  void advance(const SceneInputs& in) override {
    elastic_->advance(in);
    load_ = in.loadFactor;
  }
  std::vector<double> ux() const override { return elastic_->ux(); }
  std::vector<double> uy() const override { return elastic_->uy(); }
  std::vector<double> youngsModulus() const override { return elastic_->youngsModulus(); }
  std::vector<std::uint8_t> saveState() const override { return elastic_->saveState(); }
  void restoreState(std::span<const std::uint8_t> bytes) override { elastic_->restoreState(bytes); }

  // max |u - u_affine| / max |u_affine| over the domain points (0 before the first step or at zero load).
  double patchError() const {
    const PointCloud& c = cloud();
    const std::vector<double> ux = elastic_->ux(), uy = elastic_->uy();
    double error = 0, scale = 0;
    for (std::size_t i = 0; i < c.domain.size(); ++i) {
      const double x = c.x[c.domain[i]], y = c.y[c.domain[i]];
      const double ax = load_ * (gradient_[0] * x + gradient_[1] * y), ay = load_ * (gradient_[2] * x + gradient_[3] * y);
      error = std::max(error, std::hypot(ux[i] - ax, uy[i] - ay));
      scale = std::max(scale, std::hypot(ax, ay));
    }
    return scale > 0 ? error / scale : 0.0;
  }

 private:
  std::array<double, 4> gradient_;
  std::unique_ptr<Runner> elastic_;
  double load_ = 0;
};

void validatePatch(const SceneParameters& p) {
  for (ValueReference vr : {kStrainXX, kStrainYY, kStrainXY})
    require(std::isfinite(ownValue(p, vr)), "the patch test's strains must be finite");
  validate(patchSpecimen(p), p.grid);
}

using namespace declaration_names;

Variable strain(std::string_view name, ValueReference vr, std::string_view description, std::string_view start) {
  return {.name = name, .vr = vr, .type = T::Float64, .causality = C::Parameter, .variability = V::Fixed,
          .initial = I::Exact, .description = description, .start = start};
}

}  // namespace

SceneDeclaration patchTestScene() {
  return {
      .id = SceneId{12},
      .name = "patchTest",
      .description =
          "Patch test of the LPS discretization: a homogeneous plate whose every side's collar follows the affine "
          "field loadFactor * (strainXX x + strainXY y, strainXY x + strainYY y); patchError is the largest "
          "distance of the solved field from it over the largest displacement (round-off for a consistent "
          "discretization); quasi-static: the DefaultExperiment fits",
      .variables = {strain("strainXX", kStrainXX, "patchTest scene: du_x/dx of the affine field at loadFactor 1", "0.001"),
                    strain("strainYY", kStrainYY, "patchTest scene: du_y/dy of the affine field at loadFactor 1", "0"),
                    strain("strainXY", kStrainXY, "patchTest scene: du_x/dy = du_y/dx of the affine field at loadFactor 1",
                           "0"),
                    {.name = "patchError", .vr = kPatchError, .type = T::Float64, .causality = C::Output,
                     .variability = V::Continuous, .initial = I::Calculated,
                     .description = "patchTest scene: max |u - u_affine| / max |u_affine| over the domain points; 0 in "
                                    "the other scenes",
                     .dependencies = onLoadFactor()}},
      .outputs = {{kPatchError, [](const Runner& r) { return static_cast<const PatchTestRunner&>(r).patchError(); }}},
      .validate = validatePatch,
      .make = [](const SceneParameters& p) -> std::unique_ptr<Runner> { return std::make_unique<PatchTestRunner>(p); },
  };
}

}  // namespace peristep
