#pragma once
// Prediction of a coarse-grained fracture sample by the learned model (003 Sec. 5.2-5.4) and its errors
// against the sample's frames. Reading of 003 (which does not spell the driving out): the run starts from
// frame 0 with the frame velocity (u^1 - u^0)/Delta t_frame (003 Sec. 3.1's initial conditions); the points
// of BOmega_D (003:(29)) follow the frames, the body force is the frames' b; both linear in time between
// frames. The model's explicit stability limit is below the frame interval, so each interval is split
// into `substeps` steps.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "learning/fracture_forward.hpp"
#include "learning/fracture_residual.hpp"

namespace peristep::learning {

struct PredictionSetup {
  std::vector<char> prescribed;        // per point: follows the frames (BOmega_D)
  std::vector<double> initialStretch;  // e.g. the slit, broken from the start
  double s0 = 0.11;
  std::size_t substeps = 8;
  std::size_t lastFrame = 40;          // predicts frames 0..lastFrame
};

// The drive of a prediction: u^0 = frame 0, u^1 from the frame velocity, BOmega_D and b from the frames;
// it reads `data`, which must outlive it.
FractureDrive predictionDrive(const FractureFrames& data, const PredictionSetup& setup);
FractureRun predictFracture(const DamagedLpsOperator& op, const FractureFrames& data, const PredictionSetup& setup);

// Relative errors over frames 1..lastFrame at all points, 003 Sec. 5.1 ("averaged (in time) mean square
// errors ... normalized with respect to the ground-truth data"): sqrt(sum_f |pred_f - data_f|^2 /
// sum_f |data_f|^2); also the mean over frames of the per-frame ratio |pred_f - data_f| / |data_f|. The
// data's damage is 003:(46) of the data's own largest stretches, with the same slit and s0.
// displacementShifted: the first without the mean (over points) of pred_f - data_f, a rigid translation.
struct PredictionError {
  double displacement = 0, damage = 0;
  double displacementMean = 0, damageMean = 0;
  double displacementShifted = 0;
  double lastDamage = 0, lastDamageData = 0;  // mean damage over the points at lastFrame
  std::vector<double> frameDisplacement;       // |pred_f - data_f| / |data_f|, f = 1..lastFrame
};
PredictionError predictionError(const DamagedLpsOperator& op, const FractureFrames& data, const FractureRun& run,
                                const PredictionSetup& setup);

// The two errors above frame by frame (frames 1, 2, ... in order), as an FMU reports them while it steps:
// after frame f they equal predictionError's over frames 1..f.
class PredictionErrorSums {
 public:
  PredictionErrorSums(const DamagedLpsOperator& op, const PredictionSetup& setup, const std::vector<double>& frame0);
  // The prediction at the next frame (its u and largest stretches) against that frame of the data.
  void add(const std::vector<double>& u, const std::vector<double>& maxStretch, const std::vector<double>& frame);
  double displacement() const;  // 0 before the first frame
  double damage() const;
  std::vector<std::uint8_t> saveState() const;
  void restoreState(std::span<const std::uint8_t> bytes);

 private:
  const DamagedLpsOperator& op_;
  double s0_;
  std::vector<double> dataStretch_;  // largest stretches of the data's frames so far
  double uErr_ = 0, uRef_ = 0, phiErr_ = 0, phiRef_ = 0;
};

}  // namespace peristep::learning
