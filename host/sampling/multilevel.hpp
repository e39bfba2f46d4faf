#pragma once
// Multilevel Monte Carlo (Giles, Oper. Res. 56 (2008) 607-617): E[Q_L] = E[Q_0] + sum_l E[Q_l - Q_(l-1)],
// each term estimated from its own independent samples, a correction's two terms from the same random
// input on two grids. The arithmetic of it: sample statistics of one level, the sample counts that reach
// a standard error at least cost, and the combined estimate.
#include <cstddef>
#include <span>
#include <vector>

namespace peristep::sampling {

// Mean and unbiased variance of a level's differences Y_l (Q_0 on level 0).
struct LevelStatistics {
  std::size_t count = 0;
  double mean = 0, variance = 0;
};
LevelStatistics levelStatistics(std::span<const double> values);

// Giles (2008) Eq. (12): the counts N_l = ceil(se^-2 sqrt(V_l / C_l) sum_k sqrt(V_k C_k)) that make
// sum_l V_l / N_l <= se^2 at the least total cost sum_l N_l C_l, for variances V_l >= 0 and costs C_l > 0
// per sample of each level; each count at least `least`.
std::vector<std::size_t> optimalCounts(std::span<const double> variance, std::span<const double> cost, double se,
                                       std::size_t least);

struct MultilevelEstimate {
  double mean = 0;  // sum of the level means
  double se = 0;    // sqrt(sum_l V_l / N_l)
};
MultilevelEstimate combine(std::span<const LevelStatistics> levels);

}  // namespace peristep::sampling
