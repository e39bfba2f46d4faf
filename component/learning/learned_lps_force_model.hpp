#pragma once
// A learned LPS model on a periodic lattice as a ForceModel (internal force density -L_K[u], 003:(20)), so
// that the solvers' code (e.g. the explicit stability limit) applies to every learned kernel unchanged.
#include "learning/bernstein_kernel.hpp"
#include "learning/lattice_stencil.hpp"
#include "models/force_model.hpp"

namespace peristep::learning {

class LearnedLpsForceModel : public ForceModel {
 public:
  LearnedLpsForceModel(PeriodicLattice lattice, LatticeStencil stencil, BernsteinKernel kernel, double lambda,
                       double mu, double thickness);
  std::size_t points() const override { return lattice_.size(); }
  double pointVolume(std::size_t) const override { return lattice_.hx * lattice_.hy * thickness_; }
  void force(const double* u, double* f) override;
  // Linear model: the derivative is the force of du.
  void forceDerivative(const double*, const double* du, double* df) override { force(du, df); }
  // Column by column (the operator is linear): for the small lattices of the learning data.
  Eigen::SparseMatrix<double> tangent(const double* u) override;
  // 1/2 u.(L u) V, the energy of a linear self-adjoint operator.
  double energy(const double* u) override;

 private:
  PeriodicLattice lattice_;
  LatticeStencil stencil_;
  BernsteinKernel kernel_;
  double lambda_, mu_, thickness_;
};

}  // namespace peristep::learning
