#include "scenes/map_material.hpp"

#include "scenes/kl_material.hpp"

namespace peristep {

PointMaterial mapMaterial(const PointCloud& c, const SceneParameters& p, double& retainedVariance) {
  const SpecimenSpec& s = p.specimen;
  std::vector<double> factor(c.size(), 1.0);
  if (s.material == SpecimenMaterial::KlField) {
    const std::shared_ptr<const KlField> field = sharedKlField(c, p);
    factor = klMaterial(*field, 1.0, p);
    retainedVariance = field->retainedVarianceFraction();
  }
  PointMaterial m;
  for (std::size_t q = 0; q < c.size(); ++q) {
    const std::size_t image = imageSource(c, q).image;
    m.E.push_back(c.isVoid(q) ? 0.0 : s.youngsModulus[image] * factor[q]);
    m.nu.push_back(s.poissonRatio[image]);
    m.G.push_back(s.fractureEnergy[image]);
  }
  return m;
}

}  // namespace peristep
