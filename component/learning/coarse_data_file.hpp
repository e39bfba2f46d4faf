#pragma once
// The HDF5 layout of coarse-grained data sets (written by bench/learn_coarse_grain, read by the fit):
//   /<set>  attributes nx, ny, x0, y0, hx, hy, periodic, frame_interval [s] (0: static samples),
//           thickness [A], radius [A]; datasets rho [S][N] (amu/A^3), u [S][N][2] (A), b [S][N][2] (eV/A^4),
//           S = samples or frames, N = nx ny lattice points (row-major, x fastest).
//   /       attributes: the measured lattice constants (name -> value).
#include <map>
#include <string>
#include <vector>

#include "learning/coarse_graining.hpp"

namespace peristep::learning {

struct CoarseDataSet {
  CoarseGrid grid;
  double frameInterval = 0, thickness = 0, radius = 0;
  std::vector<CoarseFields> samples;  // samples of a static set, frames of a dynamic one
};

struct CoarseDataFile {
  std::map<std::string, double> constants;
  std::map<std::string, CoarseDataSet> sets;
};

// Both throw hdf5::Error (hdf5/hdf5_io.hpp) when HDF5 fails or a dataset's shape is not the layout's;
// reading a file that cannot be opened throws InvalidInput.
void writeCoarseData(const std::string& path, const CoarseDataFile& data);
CoarseDataFile readCoarseData(const std::string& path);

}  // namespace peristep::learning
