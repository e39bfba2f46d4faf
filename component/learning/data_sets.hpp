#pragma once
// The coarse-grained data sets of a CoarseDataFile in the forms the learning steps use: static samples
// with their weights (kernel fit) and the frames of a fracture sample (s0 step, prediction), in the
// model's units (eV, A, amu; time in sqrt(amu A^2 / eV)).
#include <vector>

#include "learning/coarse_data_file.hpp"
#include "learning/fracture_residual.hpp"
#include "learning/lps_residual.hpp"
#include "learning/model_units.hpp"

namespace peristep::learning {


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
