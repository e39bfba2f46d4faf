#pragma once
// The coarse-grained data sets of a CoarseDataFile in the forms the learning steps use: static samples
// with their weights (kernel fit) and the frames of a fracture sample (s0 step, prediction), in the
// model's units (eV, A, amu; time in sqrt(amu A^2 / eV)).
#include <vector>

#include "learning/coarse_data_file.hpp"
#include "learning/fracture_residual.hpp"
#include "learning/lps_residual.hpp"

namespace peristep::learning {

inline constexpr double kTPaPerEvA3 = 0.1602176634;  // 1 eV/A^3 = 160.2 GPa
inline constexpr double kTimeUnit = 1.0180505e-14;    // sqrt(amu A^2 / eV) in s

struct StaticData {
  PeriodicLattice lattice;
  std::vector<StaticSample> samples;
  std::vector<double> weight;  // 1 / rms(b) per sample: relative residuals
  double rho = 0;              // mean coarse-grained density [amu/A^3]
};
StaticData staticData(const CoarseDataSet& set);

// Frames of a dynamic set; the density of frame 0 for all frames.
FractureFrames fractureFrames(const CoarseDataSet& set);

}  // namespace peristep::learning
