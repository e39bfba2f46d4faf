#include "learning/prediction_window_loss.hpp"

#include <cmath>
#include <limits>
#include <utility>

#include "core/errors.hpp"

namespace peristep::learning {

PredictionWindowLoss::PredictionWindowLoss(const DamagedLpsOperator& op, const FractureFrames& data,
                                           PredictionSetup setup, std::size_t first, std::size_t last)
    : op_(op), window_{data.grid, data.interval, data.rho, {}, {}}, setup_(std::move(setup)) {
  require(first < last && last < data.u.size(), "prediction window: need first < last < frames");
  window_.u.assign(data.u.begin() + first, data.u.begin() + last + 1);
  window_.b.assign(data.b.begin() + first, data.b.begin() + last + 1);
  for (std::size_t f = 0; f <= first; ++f) op_.updateMaxStretch(data.u[f], setup_.initialStretch);
  setup_.lastFrame = last - first;
}

double PredictionWindowLoss::operator()(double s0) const {
  PredictionSetup s = setup_;
  s.s0 = s0;
  const FractureRun run = predictFracture(op_, window_, s);
  if (!run.finite) return std::numeric_limits<double>::infinity();
  double sum = 0;
  for (std::size_t f = 1; f < window_.u.size(); ++f)
    for (std::size_t k = 0; k < window_.u[f].size(); ++k) {
      const double d = run.u[f][k] - window_.u[f][k];
      sum += d * d;
    }
  return sum;
}

CriticalStretchFit learnCriticalStretch(const FractureFrames& data, const MdFractureSample& sample,
                                        const LearnedModel& model, std::size_t first, std::size_t last,
                                        std::size_t substeps, const PredictionVariant& variant) {
  const PredictionCase pc = predictionCase(data.grid, sample, model, 1.0, substeps, variant);
  const PredictionWindowLoss window(pc.op, data, pc.setup, first, last);
  const auto loss = [&](double s0AtH5) { return window(s0AtH5 * sample.s0Scale); };
  CriticalStretchFit fit = fitCriticalStretch(loss, 0.005, 0.5, 100);
  criticalStretchInterval(loss, static_cast<double>(window.frames()), fit);
  return fit;
}

}  // namespace peristep::learning
