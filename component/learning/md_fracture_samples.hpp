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
  bool edgesDriven;   // III: the vertical edge layers follow the frames; IV: free edges, body force
  double s0Scale;     // s0 ~ 1/sqrt(delta) (003 Sec. 5.4)
  const char* paper;  // 003's displacement / damage errors [%]
};

inline const std::array<MdFractureSample, 3> kMdFractureSamples{{
    {"III training, h = 5 A", "fracture_train", true, 1.0, "27 / 9"},
    {"IV test, h = 5 A", "fracture_test", false, 1.0, "58 / 15"},
    {"III training, h = 3.17 A", "fracture_train_fine", true, std::sqrt(5.0 / 3.17), "19 / 30"},
}};

// The learned model: kernel (its horizon is the learned delta), Lame moduli [eV/A^3], the spacing of the
// lattice it was learned on [A] (x; the training stencil is the bonds within delta on that lattice) and the
// critical stretch at h = 5 A (learning/prediction_window_loss.hpp; 0 where it was not learned).
struct LearnedModel {
  BernsteinKernel kernel;
  double lambda = 0, mu = 0;
  double trainingSpacing = 5.0;
  double s0 = 0;
};

// The project's learned model: the validation choice of bench/learn_lps --nonnegative-kernel (K >= 0: with 003's
// sign-changing kernels the damaged operator is unstable, docs/decisions/0015-learned-model-nonnegative-kernel.md).
constexpr double kLearnedDelta = 10.0;
constexpr int kLearnedOrder = 2;

// 003's nominal coarse spacing: 003 Sec. 5 runs delta = 20 A = 4 h on h = 5 A and keeps delta/h = 4 on the
// fine grid (Sec. 5.4).
constexpr double kPaperSpacing = 5.0;

// Choices of a prediction that bench/learn_predict varies. The defaults are the project's model, which the scene
// runs: stable at any damage with K >= 0 (tests/learning_damaged_stability_test.cpp); 003's set-up is the
// free-surface sums, the corrected dilatation and kPaperSpacing (docs/verification.md, 003).
struct PredictionVariant {
  double layer = 1.0;                // width of III's prescribed edge layers, in delta
  bool freeSurface = false;          // the free-surface sums of 003:(30) (made for the corrected dilatation)
  bool correctedDilatation = false;  // theta of 003:(31)-(32); off: DamagedLpsOperator::setCorrectedDilatation
  // delta/h on every grid is the learned delta over this spacing; 0: the model's training spacing, so that the
  // stencil has the training stencil's bonds (003 Sec. 5.4 keeps delta/h fixed too, at delta / kPaperSpacing).
  double referenceSpacing = 0;
};
constexpr PredictionVariant kPaperVariant{
    .layer = 1.0, .freeSurface = true, .correctedDilatation = true, .referenceSpacing = kPaperSpacing};

// One sample's prediction: the operator on the sample's grid and 003's set-up (the slit's bonds broken, the
// edge layers following the frames for III, s0 = s0AtH5 * s0Scale).
struct PredictionCase {
  DamagedLpsOperator op;
  PredictionSetup setup;
};
PredictionCase predictionCase(const CoarseGrid& grid, const MdFractureSample& sample, const LearnedModel& model,
                              double s0AtH5, std::size_t substeps, const PredictionVariant& variant = {});
// The horizon the prediction runs with on `grid`, and its operator there.
double predictionHorizon(const CoarseGrid& grid, const LearnedModel& model, const PredictionVariant& variant = {});
DamagedLpsOperator predictionOperator(const CoarseGrid& grid, const LearnedModel& model,
                                      const PredictionVariant& variant = {});

// The model (with its learned s0) and, per sample of kMdFractureSamples in order, its frames 0..40 and the
// frame interval [s].
struct MdFractureData {
  LearnedModel model;
  std::vector<FractureFrames> samples;
  std::vector<double> intervalSeconds;
};
void writeMdFractureData(const std::string& path, const MdFractureData& data);
// Throws InvalidInput naming the file when it cannot be read or is not such a file.
MdFractureData readMdFractureData(const std::string& path);

}  // namespace peristep::learning
