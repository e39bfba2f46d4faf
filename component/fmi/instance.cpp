#include "fmi/instance.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/errors.hpp"
#include "core/timer.hpp"
#include "fmi/model_binding.hpp"
#include "peristep.h"

namespace peristep::fmi {

namespace {

template <class T>
constexpr std::string_view requestedType() {
  if constexpr (std::is_same_v<T, double>) return "Float64";
  if constexpr (std::is_same_v<T, std::int32_t>) return "Int32";
  if constexpr (std::is_same_v<T, std::int64_t>) return "Int64";
  if constexpr (std::is_same_v<T, std::uint64_t>) return "UInt64";
}

std::string typeMismatch(const Variable& v, std::string_view requested) {
  std::string s = label(v) + " is a " + std::string(typeName(v.type)) + " variable, not " + std::string(requested);
  if (v.type == VarType::Enumeration) s += " (enumerations are read and written with fmi3GetInt64/fmi3SetInt64)";
  return s;
}

std::string number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

void requireCount(std::size_t nValues, std::size_t elements) {
  require(nValues == elements, "nValues = " + std::to_string(nValues) + " but the listed variables have " +
                                   std::to_string(elements) + " elements");
}

// Sub-nanosecond differences in the importer's time arithmetic are not a mismatch.
bool sameTime(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(1.0, std::abs(b)); }

}  // namespace

Instance::Instance(Logger logger, std::string resourcePath)
    : logger_(std::move(logger)), resourcePath_(std::move(resourcePath)) {}

Instance::~Instance() = default;

void Instance::fail(std::string_view function, std::string_view message) noexcept {
  try {
    logger_.error(std::string(function) + ": " + std::string(message));
  } catch (...) {
    logger_.error(function);  // no memory for the message: at least name the call
  }
  state_ = Terminated;
}

void Instance::enterConfigurationMode() {
  state_ = ConfigurationMode;
  logger_.event("entered Configuration Mode");
}

void Instance::exitConfigurationMode() {
  state_ = Instantiated;
  logger_.event("left Configuration Mode");
}

void Instance::enterInitializationMode(double startTime, bool stopTimeDefined, double stopTime) {
  require(std::isfinite(startTime), "startTime must be finite, got " + number(startTime));
  if (stopTimeDefined)
    require(std::isfinite(stopTime) && stopTime >= startTime,
            "stopTime must be finite and >= startTime = " + number(startTime) + ", got " + number(stopTime));
  time_ = startTime;
  stopTimeDefined_ = stopTimeDefined;
  stopTime_ = stopTime;
  state_ = InitializationMode;
  logger_.event("entered Initialization Mode at t = " + number(startTime));
}

void Instance::exitInitializationMode() {
  if (!solutionValid_) solve();
  state_ = StepMode;
  setSinceStep_ = false;
  logger_.event("entered Step Mode");
}

Instance::StepEnd Instance::doStep(double currentCommunicationPoint, double communicationStepSize) {
  require(std::isfinite(currentCommunicationPoint),
          "currentCommunicationPoint must be finite, got " + number(currentCommunicationPoint));
  require(std::isfinite(communicationStepSize) && communicationStepSize > 0,
          "communicationStepSize must be positive and finite, got " + number(communicationStepSize));
  require(sameTime(currentCommunicationPoint, time_), "currentCommunicationPoint = " +
                                                          number(currentCommunicationPoint) +
                                                          " but the FMU is at time " + number(time_));
  const double next = currentCommunicationPoint + communicationStepSize;
  if (stopTimeDefined_)
    require(next <= stopTime_ || sameTime(next, stopTime_),
            "a step to t = " + number(next) + " passes stopTime = " + number(stopTime_));
  Stopwatch watch;
  solve(communicationStepSize);
  time_ = next;
  setSinceStep_ = false;
  if (logger_.eventsOn())
    logger_.event("step to t = " + number(time_) + " at loadFactor = " +
                  number(values_.scalar<double>(PERISTEP_VR_LOAD_FACTOR)) + " in " + number(watch.seconds()) + " s");
  const bool over = model_ && model_->separated();
  if (over) logger_.event("the crack has crossed the specimen at t = " + number(time_) + ": terminateSimulation");
  return {time_, over};
}

void Instance::terminate() {
  state_ = Terminated;
  logger_.event("terminated");
}

void Instance::reset() {
  values_ = ParameterValues();
  model_.reset();
  solutionValid_ = false;
  setSinceStep_ = false;
  time_ = 0;
  stopTimeDefined_ = false;
  stopTime_ = 0;
  state_ = Instantiated;
  logger_.reset();
}

SceneModel& Instance::model() {
  if (!model_) {
    Stopwatch watch;
    auto fresh = std::make_unique<SceneModel>(setUp(values_));
    if (const std::string bad = firstNonFinite(values_, *fresh, Needs::Model); !bad.empty())
      throw SolverFailure("the scene set-up is not finite (" + bad +
                          "): a parameter too large or too small for double precision");
    model_ = std::move(fresh);
    solutionValid_ = false;
    logger_.event("scene set up (geometry, quadrature, assembly, factorization) in " + number(watch.seconds()) +
                  " s");
  }
  return *model_;
}

SceneParameters Instance::setUp(const ParameterValues& values) const {
  SceneParameters p = sceneParameters(values);
  p.resourcePath = resourcePath_;
  // Always attached (the logger drops what is switched off): fmi3SetDebugLogging may come later.
  p.progress = [this](std::string_view phase, std::uint64_t done, std::uint64_t total) {
    logger_.progress(phase, done, total);
  };
  return p;
}

void Instance::solve(double stepSize) {
  SceneModel& m = model();
  solutionValid_ = false;
  const double loadFactor = values_.scalar<double>(PERISTEP_VR_LOAD_FACTOR);
  const double loadDisplacement = values_.scalar<double>(PERISTEP_VR_LOAD_DISPLACEMENT);
  m.advance(SceneInputs{loadFactor, loadDisplacement, time_, stepSize});
  // No output leaves with fmi3OK unless it is finite: a huge but finite load, velocity or restored state
  // can overflow the dynamic models' energies without failing a solve.
  if (const std::string bad = firstNonFinite(values_, m, Needs::Solution); !bad.empty())
    throw SolverFailure("the solution is not finite (" + bad + " at loadFactor = " + number(loadFactor) +
                        ", loadDisplacement = " + number(loadDisplacement) +
                        "): a load, grip velocity, body force, material constant or restored state too large "
                        "for double precision drives it out of range");
  solutionValid_ = true;
}

template <class T>
std::size_t Instance::resolve(std::span<const fmi3ValueReference> vrs, bool forSet) const {
  std::size_t total = 0;
  for (fmi3ValueReference vr : vrs) {
    const Variable* v = findVariable(vr);
    require(v != nullptr, "unknown value reference " + std::to_string(vr));
    require(holds<T>(v->type), typeMismatch(*v, requestedType<T>()));
    const std::string refusal = forSet ? setRefusal(*v, state_) : getRefusal(*v, state_);
    require(refusal.empty(), refusal);
    total += values_.size(*v);
  }
  return total;
}

template <class T>
void Instance::get(std::span<const fmi3ValueReference> vrs, std::span<T> values) {
  // FMI 3.0 Step Mode: outputs are computed by fmi3DoStep, so reading after a write is ambiguous.
  require(!(state_ == StepMode && setSinceStep_),
          "illegal call sequence: values were set after the last fmi3DoStep; call fmi3DoStep before getting values");
  requireCount(values.size(), resolve<T>(vrs, false));
  std::size_t at = 0;
  for (fmi3ValueReference vr : vrs) {
    const Variable& v = *findVariable(vr);
    const auto out = values.subspan(at, values_.size(v));
    at += out.size();
    if (settable(v)) {
      const auto stored = values_.get<T>(vr);
      std::copy(stored.begin(), stored.end(), out.begin());
    } else if (v.causality == Causality::Independent) {
      if constexpr (std::is_same_v<T, double>) out[0] = time_;
    } else {
      const ComputedVariable& c = *findComputed(vr);
      const SceneModel* m = c.needs == Needs::Parameters ? nullptr : &model();
      if (c.needs == Needs::Solution && !solutionValid_) solve();
      if constexpr (std::is_same_v<T, double>)
        c.readFloat64(values_, m, out);
      else if constexpr (std::is_same_v<T, std::int32_t>)
        c.readInt32(values_, m, out);
      else
        throw std::logic_error("no reader of this type for " + label(v));
    }
  }
}

template <class T>
void Instance::set(std::span<const fmi3ValueReference> vrs, std::span<const T> values) {
  requireCount(values.size(), resolve<T>(vrs, true));
  // Sizes before anything changes; every value checked before any is stored, so that a rejected
  // call changes nothing.
  std::vector<std::span<const T>> parts;
  for (std::size_t at = 0; fmi3ValueReference vr : vrs) {
    const Variable& v = *findVariable(vr);
    parts.push_back(values.subspan(at, values_.size(v)));
    at += parts.back().size();
    values_.check<T>(v, parts.back());
  }
  for (std::size_t k = 0; k < vrs.size(); ++k) {
    const Variable& v = *findVariable(vrs[k]);
    if (values_.set<T>(v, parts[k])) {
      solutionValid_ = false;
      if (v.causality != Causality::Input) model_.reset();  // a new scene set-up
    }
  }
  if (state_ == StepMode && !vrs.empty()) setSinceStep_ = true;
}

void Instance::refuseType(std::string_view type, std::span<const fmi3ValueReference> vrs, std::size_t nValues) {
  for (fmi3ValueReference vr : vrs) {
    const Variable* v = findVariable(vr);
    require(v != nullptr, "unknown value reference " + std::to_string(vr));
    throw InvalidInput(typeMismatch(*v, type));
  }
  requireCount(nValues, 0);
}

const Snapshot& Instance::owned(const Snapshot* s) const {
  require(s != nullptr, "FMUState is NULL");
  const auto it = std::find_if(snapshots_.begin(), snapshots_.end(), [s](const auto& p) { return p.get() == s; });
  require(it != snapshots_.end(), "FMUState was not created by this instance or has been freed");
  return **it;
}

Snapshot* Instance::saveState(Snapshot* reuse) {
  Snapshot s{state_,         time_,        stopTimeDefined_, stopTime_, values_, solutionValid_,
             setSinceStep_, model_ != nullptr, model_ ? model_->saveState() : std::vector<std::uint8_t>{}};
  if (reuse) {
    owned(reuse);
    *reuse = std::move(s);
    return reuse;
  }
  snapshots_.push_back(std::make_unique<Snapshot>(std::move(s)));
  return snapshots_.back().get();
}

void Instance::restoreState(const Snapshot* state) {
  const Snapshot& s = owned(state);
  // The state holds every parameter, structural ones included: an instance configured otherwise
  // takes the state's structure (FMI 3.0, fmi3GetFMUState: a state holds all that is needed to continue).
  if (!s.hasModel) {
    model_.reset();
  } else if (model_ && values_.sameSetUp(s.values)) {
    model_->restoreState(s.model);  // the same scene: keep its factorization
  } else {
    auto fresh = std::make_unique<SceneModel>(setUp(s.values));
    fresh->restoreState(s.model);
    model_ = std::move(fresh);
  }
  state_ = s.state;
  time_ = s.time;
  stopTimeDefined_ = s.stopTimeDefined;
  stopTime_ = s.stopTime;
  values_ = s.values;
  solutionValid_ = s.solutionValid;
  setSinceStep_ = s.setSinceStep;
  logger_.event("FMU state restored at t = " + number(time_));
}

void Instance::freeState(Snapshot* s) {
  owned(s);
  std::erase_if(snapshots_, [s](const auto& p) { return p.get() == s; });
}

std::vector<std::uint8_t> Instance::serializeState(const Snapshot* s) const { return serialize(owned(s)); }

Snapshot* Instance::deserializeState(std::span<const std::uint8_t> bytes) {
  snapshots_.push_back(std::make_unique<Snapshot>(deserialize(bytes)));
  return snapshots_.back().get();
}

template void Instance::get<double>(std::span<const fmi3ValueReference>, std::span<double>);
template void Instance::get<std::int32_t>(std::span<const fmi3ValueReference>, std::span<std::int32_t>);
template void Instance::get<std::int64_t>(std::span<const fmi3ValueReference>, std::span<std::int64_t>);
template void Instance::get<std::uint64_t>(std::span<const fmi3ValueReference>, std::span<std::uint64_t>);
template void Instance::set<double>(std::span<const fmi3ValueReference>, std::span<const double>);
template void Instance::set<std::int32_t>(std::span<const fmi3ValueReference>, std::span<const std::int32_t>);
template void Instance::set<std::int64_t>(std::span<const fmi3ValueReference>, std::span<const std::int64_t>);
template void Instance::set<std::uint64_t>(std::span<const fmi3ValueReference>, std::span<const std::uint64_t>);

}  // namespace peristep::fmi
