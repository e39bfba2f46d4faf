#include "scenes/fracture_specimen.hpp"

#include "core/timer.hpp"
#include "fracture/bond_state.hpp"
#include "models/lps_material.hpp"
#include "quadrature/optimization_weights.hpp"

namespace peristep {

std::shared_ptr<const LpsDiscretization> specimenDiscretization(PointCloud cloud) {
  LpsDiscretization d;
  d.cloud = std::move(cloud);
  const PointCloud& c = d.cloud;
  Stopwatch clock;
  d.neighbours = findNeighbours(c, c.delta);
  d.dofs = numberDofs(c, d.neighbours);
  d.neighbourSeconds = clock.lap();
  // Weights on the full neighbourhood, Void points included: the broken-bond weights w^ of 000:(3.18)
  // then integrate over the part of the ball outside the material.
  d.weights = optimizationWeights(c, d.neighbours, std::vector<char>(c.size(), 1));
  d.weightSeconds = clock.lap();
  return std::make_shared<const LpsDiscretization>(std::move(d));
}

FractureSpecimen buildFractureSpecimen(const SpecimenSpec& s, PointCloud cloud, const PointMaterial& m,
                                       LinearSolverKind solver, FactorizationReuse reuse, FactorPrecision zonePrecision) {
  FractureSpecimen b;
  b.disc = specimenDiscretization(std::move(cloud));
  const LpsDiscretization& d = *b.disc;
  const PointCloud& c = d.cloud;
  FractureMaterial mat;
  for (std::size_t q = 0; q < c.size(); ++q) {
    const Lame l = planeStrain(m.E[q], m.nu[q]);
    mat.lambda.push_back(l.lambda);
    mat.mu.push_back(l.mu);
    mat.fractureEnergy.push_back(m.G[q]);
  }
  CollarMotion motion = collarMotion(s, c);
  b.collars = std::move(motion.collars);
  BondState bonds = makeBondState(c, d.neighbours, mat.lambda, mat.mu, mat.fractureEnergy);
  for (const Segment& crack : s.cracks) breakCrossing(bonds, c, d.neighbours, crack);
  b.E = m.E;
  b.fracture = std::make_unique<QuasiStaticFracture>(b.disc, std::move(mat), std::move(bonds), std::move(motion.unit), solver,
                                                     reuse, zonePrecision);
  return b;
}

}  // namespace peristep
