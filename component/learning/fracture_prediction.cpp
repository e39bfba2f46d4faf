#include "learning/fracture_prediction.hpp"

#include <algorithm>
#include <cmath>

#include "core/byte_stream.hpp"
#include "core/errors.hpp"

namespace peristep::learning {

namespace {

// Frames linear in time; `frame` in frame intervals, clamped to the frames there are.
void interpolate(const std::vector<std::vector<double>>& frames, double frame, std::vector<double>& out) {
  const double f = std::clamp(frame, 0.0, static_cast<double>(frames.size() - 1));
  const auto i = std::min(static_cast<std::size_t>(f), frames.size() - 2);
  const double w = f - static_cast<double>(i);
  out.resize(frames[i].size());
  for (std::size_t k = 0; k < out.size(); ++k) out[k] = (1.0 - w) * frames[i][k] + w * frames[i + 1][k];
}

struct Sums {
  double err = 0, ref = 0, meanRatio = 0;
  double add(const std::vector<double>& pred, const std::vector<double>& data) {  // the frame's ratio
    double e = 0, r = 0;
    for (std::size_t k = 0; k < data.size(); ++k)
      e += (pred[k] - data[k]) * (pred[k] - data[k]), r += data[k] * data[k];
    err += e, ref += r;
    const double ratio = r > 0 ? std::sqrt(e / r) : 0.0;
    meanRatio += ratio;
    return ratio;
  }
};

}  // namespace

FractureDrive predictionDrive(const FractureFrames& data, const PredictionSetup& s) {
  require(s.lastFrame >= 1 && s.lastFrame < data.u.size() && s.substeps >= 1, "prediction: frames out of range");
  FractureDrive d;
  d.rho = data.rho;
  d.prescribed = s.prescribed;
  d.initialStretch = s.initialStretch;
  d.u0 = data.u[0];
  interpolate(data.u, 1.0 / static_cast<double>(s.substeps), d.u1);  // u0 + dt (u^1 - u^0) / Delta t_frame
  d.boundary = [&data](double t, std::vector<double>& u) { interpolate(data.u, t / data.interval, u); };
  d.body = [&data](double t, std::vector<double>& b) { interpolate(data.b, t / data.interval, b); };
  return d;
}

FractureRun predictFracture(const DamagedLpsOperator& op, const FractureFrames& data, const PredictionSetup& s) {
  const FractureDrive d = predictionDrive(data, s);
  return runFracture(op, d, s.s0, data.interval / static_cast<double>(s.substeps), s.lastFrame * s.substeps,
                     s.substeps);
}

PredictionErrorSums::PredictionErrorSums(const DamagedLpsOperator& op, const PredictionSetup& s,
                                         const std::vector<double>& frame0)
    : op_(op), s0_(s.s0), dataStretch_(s.initialStretch) {
  op.updateMaxStretch(frame0, dataStretch_);
}

void PredictionErrorSums::add(const std::vector<double>& u, const std::vector<double>& maxStretch,
                              const std::vector<double>& frame) {
  op_.updateMaxStretch(frame, dataStretch_);
  Sums a{uErr_, uRef_}, b{phiErr_, phiRef_};
  a.add(u, frame);
  b.add(op_.damage(maxStretch, s0_), op_.damage(dataStretch_, s0_));
  uErr_ = a.err, uRef_ = a.ref, phiErr_ = b.err, phiRef_ = b.ref;
}

double PredictionErrorSums::displacement() const { return uRef_ > 0 ? std::sqrt(uErr_ / uRef_) : 0.0; }
double PredictionErrorSums::damage() const { return phiRef_ > 0 ? std::sqrt(phiErr_ / phiRef_) : 0.0; }

std::vector<std::uint8_t> PredictionErrorSums::saveState() const {
  ByteWriter w;
  w.putArray(dataStretch_);
  for (const double v : {uErr_, uRef_, phiErr_, phiRef_}) w.put(v);
  return w.take();
}

void PredictionErrorSums::restoreState(std::span<const std::uint8_t> bytes) {
  ByteReader r(bytes);
  auto stretch = r.getArray<double>(dataStretch_.size());
  const double e = r.get<double>(), f = r.get<double>(), g = r.get<double>(), h = r.get<double>();
  r.expectEnd();
  dataStretch_ = std::move(stretch);
  uErr_ = e, uRef_ = f, phiErr_ = g, phiRef_ = h;
}

PredictionError predictionError(const DamagedLpsOperator& op, const FractureFrames& data, const FractureRun& run,
                                const PredictionSetup& s) {
  require(run.finite && run.u.size() == s.lastFrame + 1, "prediction error: the run did not reach the last frame");
  Sums u, phi, shifted;
  double lastDamage = 0, lastDamageData = 0;
  std::vector<double> frameRatio;
  std::vector<double> smax = s.initialStretch;
  for (std::size_t f = 0; f <= s.lastFrame; ++f) {
    op.updateMaxStretch(data.u[f], smax);
    if (f == 0) continue;
    frameRatio.push_back(u.add(run.u[f], data.u[f]));
    const std::vector<double> pred = op.damage(run.maxStretch[f], s.s0), truth = op.damage(smax, s.s0);
    phi.add(pred, truth);
    if (f == s.lastFrame)
      for (std::size_t p = 0; p < pred.size(); ++p)
        lastDamage += pred[p] / pred.size(), lastDamageData += truth[p] / pred.size();
    double mean[2] = {0, 0};  // of pred - data per component
    const double points = static_cast<double>(data.u[f].size() / 2);
    for (std::size_t k = 0; k < data.u[f].size(); ++k) mean[k % 2] += (run.u[f][k] - data.u[f][k]) / points;
    std::vector<double> back = run.u[f];
    for (std::size_t k = 0; k < back.size(); ++k) back[k] -= mean[k % 2];
    shifted.add(back, data.u[f]);
  }
  const auto frames = static_cast<double>(s.lastFrame);
  return {std::sqrt(u.err / u.ref), std::sqrt(phi.err / phi.ref), u.meanRatio / frames, phi.meanRatio / frames,
          std::sqrt(shifted.err / shifted.ref), lastDamage, lastDamageData, frameRatio};
}

}  // namespace peristep::learning
