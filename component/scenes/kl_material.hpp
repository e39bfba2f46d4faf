#pragma once
// The Karhunen-Loeve random material factor of the KL plate and of a specimen with materialField klField
// (000 Sec. 2.2): E0 (1 + g) or E0 exp(g - v/2) at every point of a cloud, g from the scene's xi, covariance,
// correlation length and standard deviation.
#include <memory>
#include <vector>

#include "geometry/point_cloud.hpp"
#include "random/kl_field.hpp"
#include "scenes/scene_model.hpp"

namespace peristep {

// The modes of the last field asked for (the samples of one study share them).
std::shared_ptr<const KlField> sharedKlField(const PointCloud& c, const SceneParameters& p);

// The material with mean E0 at every point of the field's cloud for p's xi and transform.
std::vector<double> klMaterial(const KlField& field, double E0, const SceneParameters& p);

}  // namespace peristep
