#include "scenes/kl_material.hpp"

#include <mutex>

namespace peristep {

namespace {

KlSpec klSpec(const SceneParameters& p) {
  KlSpec s;
  s.kind = p.covariance;
  s.correlationLength = p.correlationLength;
  s.standardDeviation = p.fieldStd;
  s.modes = p.xi.size();
  return s;
}

}  // namespace

std::shared_ptr<const KlField> sharedKlField(const PointCloud& c, const SceneParameters& p) {
  const GridSpec& grid = p.grid;
  const KlSpec spec = klSpec(p);
  static std::mutex mutex;
  static GridSpec lastGrid;
  static KlSpec lastSpec;
  static std::shared_ptr<const KlField> last;
  std::lock_guard lock(mutex);
  const bool same = last && lastGrid.sameCloud(grid) && lastSpec.kind == spec.kind &&
                    lastSpec.correlationLength == spec.correlationLength &&
                    lastSpec.standardDeviation == spec.standardDeviation && lastSpec.modes == spec.modes;
  if (!same) {
    last = std::make_shared<const KlField>(c.x, c.y, c.h, spec);
    lastGrid = grid;
    lastSpec = spec;
  }
  return last;
}

std::vector<double> klMaterial(const KlField& field, double E0, const SceneParameters& p) {
  return field.materialField(E0, p.xi, p.transform);
}

}  // namespace peristep
