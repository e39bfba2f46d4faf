#pragma once
// The material of a specimen given by its maps (scenes/specimen.hpp), on every point of its cloud.
#include "scenes/fracture_specimen.hpp"
#include "scenes/scene_model.hpp"

namespace peristep {

// The maps' material at each point's nearest image point (collar included); with materialField klField E
// times the KL factor of mean 1 (scenes/kl_material.hpp), whose retained variance is written to
// `retainedVariance`; E = 0 on Void.
PointMaterial mapMaterial(const PointCloud& c, const SceneParameters& p, double& retainedVariance);

}  // namespace peristep
