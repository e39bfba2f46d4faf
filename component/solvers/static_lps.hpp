#pragma once
// Quasi-static heterogeneous LPS without fracture: assemble once, factorize once, solve per load.
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "linalg/linear_solver.hpp"
#include "models/elastic_scene.hpp"
#include "models/lps_discretization.hpp"

namespace peristep {

struct StaticTimes {
  double assembly = 0, factorization = 0, solve = 0;
};

// A material given point by point, and the collar's displacement at load 1 ((u_x, u_y) of every point, read
// on the collar); intact: the bonds of a cloud with Void points or pre-cracks, empty when all are intact.
struct StaticLoading {
  std::vector<double> lambda, mu, unitCollar;
  std::vector<std::uint8_t> intact;
};

class StaticLps {
 public:
  // Evaluates the material on every point (rejecting E <= 0 with the offending location), assembles
  // the (u, theta) system and factorizes it.
  // intact: as in StaticLoading (the bonds across a pre-crack absent), empty when all are intact.
  StaticLps(std::shared_ptr<const LpsDiscretization> disc, const ElasticScene& scene,
            LinearSolverKind solver = LinearSolverKind::Umfpack, std::vector<std::uint8_t> intact = {});
  // The same without body force, for a material and collar data given as arrays (no exact solution:
  // errorL2 is not available).
  StaticLps(std::shared_ptr<const LpsDiscretization> disc, StaticLoading loading,
            LinearSolverKind solver = LinearSolverKind::Umfpack);

  // Displacement for body force and collar data scaled by loadFactor (the problem is linear).
  void solve(double loadFactor = 1.0);

  const LpsDiscretization& discretization() const { return *disc_; }
  std::int64_t unknowns() const { return disc_->dofs.size; }
  const StaticTimes& times() const { return times_; }
  // Displacement on the domain points, in image order [ny][nx].
  const std::vector<double>& ux() const { return ux_; }
  const std::vector<double>& uy() const { return uy_; }
  // sqrt(sum_i |u_i - s u0(x_i)|^2 h^2) over the domain points against the scene's displacement u0
  // scaled by the load factor s: of the last solve, or of a given field.
  double errorL2() const { return errorL2At(ux_, uy_, load_); }
  double errorL2At(const std::vector<double>& ux, const std::vector<double>& uy, double loadFactor) const;
  // The bonds' state (empty: all intact).
  const std::vector<std::uint8_t>& intact() const { return loading_.intact; }
  // (u_x, u_y) of every point at the last solve: the solution, load times the collar data on the collar.
  const std::vector<double>& displacement() const { return u_; }
  // Force of the marked collar points on the domain at the last solve [N/m] (models/collar_force.hpp).
  std::array<double, 2> collarForce(const std::vector<std::uint8_t>& collar) const;

 private:
  // Assembles and factorizes; returns the points of pieces that nothing holds (held at rest).
  std::vector<std::size_t> setUp(LinearSolverKind solver);

  std::shared_ptr<const LpsDiscretization> disc_;
  const ElasticScene* scene_ = nullptr;
  StaticLoading loading_;
  LpsSystem system_;
  std::vector<double> rhs0_;  // f - B g for loadFactor = 1
  std::unique_ptr<LinearSolver> solver_;
  StaticTimes times_;
  double load_ = 0;
  std::vector<double> x_, u_, ux_, uy_;
};

}  // namespace peristep
