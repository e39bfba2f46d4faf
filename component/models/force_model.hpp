#pragma once
// What a time integrator needs from a peridynamic model: the internal force density of a displacement
// field, its linearization and the stored energy. Fields are interleaved (x, y) per point.
#include <cstddef>

#include <Eigen/SparseCore>

namespace peristep {

class ForceModel {
 public:
  virtual ~ForceModel() = default;

  virtual std::size_t points() const = 0;
  virtual double pointVolume(std::size_t p) const = 0;  // V_p (area x unit thickness in 2D)

  // Internal force density L(u) [N/m^3] (001:(13)). Models keep scratch space, hence non-const;
  // one model must not be evaluated from two threads at once.
  virtual void force(const double* u, double* f) = 0;
  // Directional derivative (dL/du)(u) du.
  virtual void forceDerivative(const double* u, const double* du, double* df) = 0;
  // dL/du at u, 2N x 2N.
  virtual Eigen::SparseMatrix<double> tangent(const double* u) = 0;
  // Stored energy PD(u) [J per unit thickness] (001:(11)).
  virtual double energy(const double* u) = 0;
};

}  // namespace peristep
