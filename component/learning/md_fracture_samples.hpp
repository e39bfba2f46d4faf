#pragma once
// The MD fracture samples of 003 Sec. 5 as the project predicts them (bench/learn_predict and the FMU's
// learnedFracture scene): which coarse-grained set, the horizon, the driven edges and s0's scaling; the
// set-up of one prediction; and the file that carries the learned model and the samples' frames into the
// FMU's resources (written at build time from data/learning/graphene_md.h5, read without HDF5).
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "learning/bernstein_kernel.hpp"
#include "learning/fracture_prediction.hpp"

namespace peristep::learning {

struct MdFractureSample {
  const char* name;
  const char* set;    // data set of the coarse-grained file
  double deltaPerH;   // 0: the learned horizon; else delta = deltaPerH * h (003 Sec. 5.4: 4 h)
  bool edgesDriven;   // III: the vertical edge layers follow the frames; IV: free edges, body force
  double s0Scale;     // s0 ~ 1/sqrt(delta) (003 Sec. 5.4)
  const char* paper;  // 003's displacement / damage errors [%]
};

inline const std::array<MdFractureSample, 3> kMdFractureSamples{{
    {"III training, h = 5 A", "fracture_train", 0, true, 1.0, "27 / 9"},
    {"IV test, h = 5 A", "fracture_test", 0, false, 1.0, "58 / 15"},
    {"III training, h = 3.17 A", "fracture_train_fine", 4, true, std::sqrt(5.0 / 3.17), "19 / 30"},
}};

// The learned model: kernel (its horizon is the learned delta) and Lame moduli [eV/A^3].
struct LearnedModel {
  BernsteinKernel kernel;
  double lambda = 0, mu = 0;
};

// One sample's prediction: the operator on the sample's grid and 003's set-up (the slit's bonds broken, the
// edge layers `layer` horizons wide following the frames for III, s0 = s0AtH5 * s0Scale). horizon > 0
// replaces the sample's horizon rule (bench/learn_predict --matched-horizon).
struct PredictionCase {
  DamagedLpsOperator op;
  PredictionSetup setup;
};
PredictionCase predictionCase(const CoarseGrid& grid, const MdFractureSample& sample, const LearnedModel& model,
                              double s0AtH5, std::size_t substeps, double layer = 1.0, bool freeSurface = true,
                              double horizon = 0);

// The model and, per sample of kMdFractureSamples in order, its frames 0..40 and the frame interval [s].
struct MdFractureData {
  LearnedModel model;
  std::vector<FractureFrames> samples;
  std::vector<double> intervalSeconds;
};
void writeMdFractureData(const std::string& path, const MdFractureData& data);
// Throws InvalidInput naming the file when it cannot be read or is not such a file.
MdFractureData readMdFractureData(const std::string& path);

}  // namespace peristep::learning
