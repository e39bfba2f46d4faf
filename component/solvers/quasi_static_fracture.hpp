#pragma once
// Quasi-static brittle fracture with the heterogeneous LPS model (000 Sec. 3.3, Sec. 5): at each load
// solve, break every bond over its critical stretch, re-solve at the same load until no new bond breaks.
#include <array>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "fracture/bond_state.hpp"
#include "models/lps_discretization.hpp"
#include "solvers/linear_solver.hpp"

namespace peristep {

struct FractureMaterial {
  std::vector<double> lambda, mu, fractureEnergy;  // per point
};

struct LoadStepReport {
  int subIterations = 0;       // solves at this load
  int factorizations = 0;      // numeric factorizations among them
  int krylovIterations = 0;    // GMRES iterations preconditioned by an older factorization
  std::size_t newlyBroken = 0; // pairs broken at this load
};

class QuasiStaticFracture {
 public:
  // unitCollarDisplacement: (u_x, u_y) of every point for load 1; the collar follows load * it
  // (the problem has no body force).
  QuasiStaticFracture(std::shared_ptr<const LpsDiscretization> disc, FractureMaterial material, BondState bonds,
                      std::vector<double> unitCollarDisplacement, const std::string& solverName = "umfpack");

  LoadStepReport advance(double load);

  const LpsDiscretization& discretization() const { return *disc_; }
  const BondState& bonds() const { return bonds_; }
  // (u_x, u_y) of every point (the collar included).
  const std::vector<double>& displacement() const { return u_; }
  double load() const { return load_; }
  // Pairs broken by loading so far (CSR positions), in breaking order.
  const std::vector<std::size_t>& brokenByLoading() const { return brokenByLoading_; }
  // Net force the points of `collar` exert on the domain (per unit thickness).
  std::array<double, 2> collarForce(const std::vector<std::uint8_t>& collar) const;

  // Checkpoint of what changes while loading: load, displacement, bond state, broken list.
  std::vector<std::uint8_t> saveState() const;
  void restoreState(std::span<const std::uint8_t> bytes);

 private:
  void assemble();
  void solveCurrent(LoadStepReport& report);

  std::shared_ptr<const LpsDiscretization> disc_;
  FractureMaterial material_;
  BondState bonds_;
  std::vector<double> unitCollar_;
  std::unique_ptr<LinearSolver> solver_;
  LpsSystem system_;
  bool factorizationCurrent_ = false, analyzed_ = false;
  int lastKrylovIterations_ = 0;
  std::vector<double> u_, x_;  // u of all points; last unknown vector (warm start)
  std::vector<std::uint8_t> stabilized_;
  std::vector<std::size_t> brokenByLoading_;
  double load_ = 0;
};

}  // namespace peristep
