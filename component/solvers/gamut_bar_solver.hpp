#pragma once
// Quasi-static force-controlled loading of a GamutBar (002:(25) without inertia): the end x = L is
// pulled by F, the end x = 0 is fixed. Every element is elastic until its cap, then slips at constant
// force (002:(35), see gamut_bar.hpp), so a load step minimizes a convex, piecewise-quadratic potential:
// Newton on the current set of elastic elements with a backtracking line search, the dense Cholesky
// factor of the tangent reused as long as it still converges fast (modified Newton) and refactored when
// elements have switched and it no longer does. Elements whose critical strain lies beyond
// `linearStrain` cannot slip while no local bond is strained that far (an element's strain is an
// average of local strains); they are summed once into a constant matrix, and every step checks the bound.
// The nonlocal bonds' elements are evaluated as SIMD rows (gamut_pair_kernels.hpp), the local bonds'
// element by element; the single-precision factor is DenseCholesky (dense_cholesky.hpp).
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Dense>

#include "core/errors.hpp"
#include "linalg/dense_cholesky.hpp"
#include "models/gamut_bar.hpp"
#include "solvers/gamut_pair_kernels.hpp"

namespace peristep {

struct GamutBarOutput {
  double stress = 0;  // F / A [Pa]
  double strain = 0;  // u(L) / L
  // Bonds with an element that stopped absorbing energy in this step (slipping, 002:(35)).
  std::size_t brokenBonds = 0;
};

// A local strain passed the solver's linearStrain: rerun with a larger one (infinity: no linear part).
struct LinearRangeExceeded : SolverFailure {
  using SolverFailure::SolverFailure;
};

struct GamutSolverCounters {
  std::size_t steps = 0, iterations = 0, evaluations = 0, factorizations = 0, substeps = 0;
  GamutSolverCounters& operator+=(const GamutSolverCounters& o) {
    steps += o.steps;
    iterations += o.iterations;
    evaluations += o.evaluations;
    factorizations += o.factorizations;
    substeps += o.substeps;
    return *this;
  }
};

class GamutBarSolver {
 public:
  // linearStrain <= 0: four times the material's eps_f; infinity: every element may slip.
  explicit GamutBarSolver(const GamutBar& bar, double linearStrain = 0);

  // Moves the end force from its last value to `force` [N] and returns the equilibrium reached. Throws
  // SolverFailure if none is found (the state is then that of the last bisected sub-step reached), and
  // LinearRangeExceeded (state of the last step) when a local strain passes linearStrain.
  GamutBarOutput step(double force);

  double force() const { return force_; }
  // Displacements u_1 .. u_n of the last equilibrium (u_0 = 0).
  const Eigen::VectorXd& displacement() const { return uCommitted_; }
  const GamutSolverCounters& counters() const { return counters_; }
  std::size_t activeElements() const { return activeElements_; }

 private:
  bool solveTo(double force);  // Newton from the committed state; false: no convergence
  // Residual, Pi (energy_) and, if asked, the tangent at u_; returns max |residual|.
  double evaluate(double force, bool updateTangent);
  void commit(double force);
  void factorize();
  void useElasticTangent();
  // Tangent of pair j with the elastic bits `state`; K += k g g^T of pair j's bond.
  double pairTangent(std::size_t j, std::uint8_t state) const {
    return ((state & 1) ? kA_[j] : 0.0) + ((state & 2) ? kB_[j] : 0.0);
  }
  void addPair(Eigen::MatrixXd& K, std::size_t j, double k) const;
  void addChangedPairs();  // the changes of the pairs' elastic bits into tangent_
  gamut::PairElements pairElements() const;

  const GamutBar& bar_;
  int n_;
  double linearStrain_;
  // The nonlocal bonds with elements that may slip, as rows of at most two elements per bond
  // (gamut_pair_kernels.hpp): stiffness, slip elongation (cap / k), offset (committed slip, elongation
  // units), the bar's bond of each (-1: padding), and the elastic bits of the last evaluation and of tangent_.
  std::vector<gamut::PairRow> rows_;
  std::vector<double> kA_, kB_, sA_, sB_, offsetA_, offsetB_;
  std::vector<long> pairBond_;
  std::vector<std::uint8_t> trialState_, tangentState_;
  std::size_t slippingPairs_ = 0;
  std::vector<double> diagonalChange_, lastRowChange_;  // by point, for addChangedPairs
  // The local bonds with elements that may slip (many elements each), element by element; slot_: the
  // points of the bond's unknowns (point 0, the fixed end, for no term).
  std::vector<std::array<int, 3>> unknown_, slot_;
  std::vector<std::array<double, 3>> coef_;
  std::vector<std::size_t> first_;
  std::vector<double> stiffness_, cap_, halfSlip_, offset_;
  // The tangent each local bond has in tangent_, in elastic_, and at the last evaluation.
  std::vector<double> bondTangent_, elasticBondTangent_, trialTangent_;
  std::vector<unsigned char> bondSlipping_;
  Eigen::MatrixXd linear_, elastic_, tangent_;  // lower triangles are used
  Eigen::LLT<Eigen::MatrixXd> elasticFactor_;
  DenseCholesky<float> factor_;
  DenseCholesky<double> factorDouble_;  // once a step failed with the single-precision factor
  bool usingElasticFactor_ = true, tangentIsElastic_ = true, tangentChanged_ = false;
  bool doublePrecision_ = false, refactor_ = false;
  std::size_t activeElements_ = 0;
  // Displacements and residual by point (entry 0: the fixed end; zeros beyond n for the rows' padding).
  Eigen::VectorXd u_, uCommitted_, residual_, padded_, paddedResidual_;
  double force_ = 0, lastIncrement_ = 0, energy_ = 0;
  GamutSolverCounters counters_;
};

}  // namespace peristep
