#pragma once
// The damage-criterion step by the prediction's error instead of the equation residual 003:(42): on the MD
// fracture samples (42) falls monotonically towards s0 -> 0 (the learned model's force misfits the frames'
// accelerations more than no force at all; docs/decisions/0016-s0-from-prediction-error.md), so it names no s0.
// Here the prediction is restarted at frame `first` of the sample (u^0 = that frame, its frame velocity, the largest
// stretches of frames 0..first) and run to frame `last`; the loss is its squared displacement error summed
// over frames first+1..last, minimized over s0 by learning/critical_stretch_fit.hpp.
#include <cstddef>

#include "learning/critical_stretch_fit.hpp"
#include "learning/fracture_prediction.hpp"
#include "learning/md_fracture_samples.hpp"

namespace peristep::learning {

class PredictionWindowLoss {
 public:
  // setup: the sample's prediction set-up (its s0 and lastFrame are replaced); `op` must outlive the loss.
  PredictionWindowLoss(const DamagedLpsOperator& op, const FractureFrames& data, PredictionSetup setup,
                       std::size_t first, std::size_t last);
  // sum over frames first+1..last and all points of |u_pred - u_data|^2; +infinity when the run blows up.
  double operator()(double s0) const;
  std::size_t frames() const { return window_.u.size() - 1; }

 private:
  const DamagedLpsOperator& op_;
  FractureFrames window_;
  PredictionSetup setup_;
};

// The project's s0 step on an MD fracture sample (003: frames 5-20 of sample III): the loss above for the
// prediction's operator and set-up on the sample's grid (data.grid), minimized on [0.005, 0.5] (100 scan points),
// with its 95% interval counting each frame as one observation (points within a frame are not independent: a
// smooth field).
// s0 is returned at h = 5 A (divided by the sample's s0Scale).
CriticalStretchFit learnCriticalStretch(const FractureFrames& data, const MdFractureSample& sample,
                                        const LearnedModel& model, std::size_t first = 5, std::size_t last = 20,
                                        std::size_t substeps = 8, const PredictionVariant& variant = {});

}  // namespace peristep::learning
