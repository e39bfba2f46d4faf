#pragma once
// A specimen (scenes/specimen.hpp) set up for the quasi-static LPS fracture driver (000 Sec. 3.3): the one
// construction behind the importer's specimen, the glassCeramic scene and bench/glass_ceramic.
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "models/lps_discretization.hpp"
#include "scenes/specimen.hpp"
#include "solvers/quasi_static_fracture.hpp"

namespace peristep {

// Material of every point of the cloud, collar included: Young's modulus [Pa], Poisson ratio, fracture
// energy [J/m^2]. Void points have no bonds, so what they hold is not read.
struct PointMaterial {
  std::vector<double> E, nu, G;
};

struct FractureSpecimen {
  std::shared_ptr<const LpsDiscretization> disc;
  std::vector<double> E;                              // per point [Pa]
  std::array<std::vector<std::uint8_t>, 4> collars;  // by Side: 1 on that held grip's collar points
  std::unique_ptr<QuasiStaticFracture> fracture;
};

// Neighbours, unknowns and quadrature weights of a specimen's cloud (weights on the full neighbourhood, Void
// points included, for the broken-bond weights of 000:(3.18)).
std::shared_ptr<const LpsDiscretization> specimenDiscretization(PointCloud cloud);

// `cloud` is specimenCloud(s, grid). Builds neighbours, dofs and weights, the bonds of `material` with those
// crossing a pre-crack broken, and the driver that moves each held collar by load * (ux, uy).
FractureSpecimen buildFractureSpecimen(const SpecimenSpec& s, PointCloud cloud, const PointMaterial& material,
                                       LinearSolverKind solver, FactorizationReuse reuse = FactorizationReuse::CrackZone,
                                       FactorPrecision zonePrecision = kZoneFactorPrecision);

}  // namespace peristep
