#pragma once
// The learned LPS operator of 003:(17)-(18) on a periodic lattice and the equation residual of static
// samples, 003:(40) with u'' = 0: r = L_K[u] - b. For a fixed kernel, L_K[u] = lambda A_K[u] + mu (G_K[u] -
// A_K[u]) is linear in (lambda, mu), with A the dilatation part and G the deviatoric part; in the kernel
// coefficients D it is a ratio of a quadratic (A) or linear (G) form and powers of m = sum_k D_k m_k.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "learning/bernstein_kernel.hpp"
#include "learning/lattice_stencil.hpp"

namespace peristep::learning {

inline constexpr double kC1 = 2.0, kC2 = 16.0, kDim = 2.0;  // 2D constants of 003:(14)-(15)

// A displacement field and the body force that holds it, interleaved (x, y) per lattice point.
struct StaticSample {
  std::vector<double> u, b;
};

// L_K[u] straight from 003:(17)-(18) (every point has the full stencil: periodic lattice).
std::vector<double> applyLearnedLps(const PeriodicLattice& lattice, const LatticeStencil& stencil,
                                    const BernsteinKernel& kernel, double lambda, double mu,
                                    const std::vector<double>& u);

// The residual columns of many samples, each sample's rows scaled by weight[m] (e.g. 1/rms(b)). The
// kernel-independent sums per basis function are built once per alpha; a new D then costs O(points P^2).
class StaticResidual {
 public:
  StaticResidual(PeriodicLattice lattice, LatticeStencil stencil, int order, std::vector<StaticSample> samples,
                 std::vector<double> weight);
  std::size_t rows() const { return rhs_.size(); }
  const std::vector<double>& rhs() const { return rhs_; }  // weighted b
  // Columns multiplying lambda and mu for the kernel (alpha, D), D with order()+1 entries.
  void columns(double alpha, const std::vector<double>& D, std::vector<double>& lambdaColumn,
               std::vector<double>& muColumn);
  int order() const { return order_; }
  double delta() const { return stencil_.delta; }

 private:
  struct Sums {
    double alpha;
    std::vector<double> mk, g, a;
  };
  const Sums& sums(double alpha);  // from the cache or built
  Sums build(double alpha) const;

  PeriodicLattice lattice_;
  LatticeStencil stencil_;
  int order_;
  std::vector<StaticSample> samples_;
  std::vector<double> weight_, rhs_;
  std::vector<std::uint32_t> neighbour_;  // [p * stencil size + s]
  // Per alpha: m_k; g[row (P+1) + k]; a[(row (P+1) + k) (P+1) + l], row = 2 p + c over all samples. The
  // last few are kept: a Levenberg-Marquardt iteration visits alpha, alpha +- h and a trial alpha.
  std::vector<Sums> cache_;
};

}  // namespace peristep::learning
