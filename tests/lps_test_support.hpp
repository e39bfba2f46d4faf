#pragma once
// Small helpers shared by the LPS tests: run one refinement level and return its L2 error.
#include <cmath>
#include <memory>
#include <vector>

#include "models/elastic_scene.hpp"
#include "solvers/static_lps.hpp"

namespace peristep::testing {

inline GridSpec squareGrid(int level, double side, double deltaOverH = 3.0, double jitter = 0.0) {
  GridSpec g;
  g.nx = g.ny = static_cast<std::size_t>(level) + 1;
  g.Lx = g.Ly = side;
  g.deltaOverH = deltaOverH;
  g.jitter = jitter;
  return g;
}

inline double levelError(const ElasticScene& scene, const GridSpec& grid,
                         LinearSolverKind solver = LinearSolverKind::Umfpack) {
  auto disc = std::make_shared<const LpsDiscretization>(LpsDiscretization::build(grid));
  StaticLps lps(disc, scene, solver);
  lps.solve();
  return lps.errorL2();
}

// Observed rates log(e_k/e_{k+1})/log(2) between successive levels that halve h.
inline std::vector<double> halvingRates(const std::vector<double>& errors) {
  std::vector<double> r;
  for (std::size_t k = 1; k < errors.size(); ++k) r.push_back(std::log2(errors[k - 1] / errors[k]));
  return r;
}

}  // namespace peristep::testing
