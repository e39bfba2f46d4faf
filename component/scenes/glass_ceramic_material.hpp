#pragma once
// The glass-ceramic material of 000 Sec. 5 on a specimen's cloud: the crystal field R (the microstructure
// of a seed, R in {0, 1}, or the PCA expansion 000:(5.5)) and the phases' E and G affine in R. The one
// piece of the glassCeramic scene that is its own physics; the plate, pre-crack and grips are a specimen.
#include <cstdint>
#include <memory>
#include <vector>

#include "fracture/toughness.hpp"
#include "geometry/point_cloud.hpp"
#include "random/microstructure_pca.hpp"
#include "scenes/fracture_specimen.hpp"

namespace peristep {

struct SceneParameters;

struct CrystalField {
  std::vector<double> R;              // per point of the cloud, collar included, in [0, 1]
  std::vector<std::uint8_t> crystal;  // the crack shares' phase: R >= 1/2
  double fraction = 0;                // crystal fraction measured on the domain points
  std::shared_ptr<const PcaModes> pca;  // the modes R was expanded from (empty: a microstructure)
};

// The microstructure of `seed` at the target fraction.
CrystalField microstructureField(const PointCloud& cloud, double fraction, std::uint64_t seed);
// A given field, one value per cloud point (e.g. a PCA expansion made elsewhere); throws InvalidInput for
// a wrong length.
CrystalField givenField(const PointCloud& cloud, std::vector<double> R);
// The scene's: with pcaRealizations > 0 the PCA field of that many microstructures (seeds 1..n, computed
// once per process and cloud) at the coordinates xi, clipped to [0, 1]; else the microstructure of seed.
CrystalField crystalField(const PointCloud& cloud, const SceneParameters& p);

// Scales of the standardized coordinates of a PCA field: xi_k = sqrt(lambda_k) eta_k
// (random/microstructure_pca.hpp); empty for a microstructure.
std::vector<double> pcaScales(const CrystalField& field);

// The phases of 000 Table 1 as the scene's parameters set them (glass/crystal E and G, poissonRatio).
PhaseConstants phaseConstants(const SceneParameters& p);
// Throws InvalidInput for a non-physical phase (E <= 0, nu outside (-1, 0.5), G <= 0).
void validate(const PhaseConstants& m);
// 000:(5.5): E and G affine in R, one nu. Throws InvalidInput where they are not positive.
PointMaterial phaseMaterial(const PointCloud& cloud, const std::vector<double>& R, const PhaseConstants& m);

}  // namespace peristep
