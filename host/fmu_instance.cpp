#include "fmu_instance.hpp"

#include <cstdlib>
#include <iostream>
#include <utility>

#include "host_errors.hpp"

namespace peristep::host {

namespace {

const char* statusName(fmi3Status s) {
  switch (s) {
    case fmi3OK: return "fmi3OK";
    case fmi3Warning: return "fmi3Warning";
    case fmi3Discard: return "fmi3Discard";
    case fmi3Error: return "fmi3Error";
    case fmi3Fatal: return "fmi3Fatal";
  }
  return "an unknown status";
}

// Messages go into one-line error reports.
std::string oneLine(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

template <class C, class Source>
std::vector<C> narrow(const Source& values) {
  return std::vector<C>(values.begin(), values.end());
}

}  // namespace

struct FmuInstance::LogSink {
  struct Message {
    fmi3Status status;
    std::string category, text;
  };
  std::string instanceName;
  bool verbose = false;
  std::vector<Message> messages;
  decltype(Options::progress) progress;

  // 'progress: <phase> <done>/<total>' -> progress(phase, done, total); false for any other text.
  bool forwardProgress(std::string_view text) const {
    constexpr std::string_view prefix = "progress: ";
    if (!progress || !text.starts_with(prefix)) return false;
    text.remove_prefix(prefix.size());
    const auto space = text.rfind(' '), slash = text.rfind('/');
    if (space == std::string_view::npos || slash == std::string_view::npos || slash < space) return false;
    const std::string done(text.substr(space + 1, slash - space - 1)), total(text.substr(slash + 1));
    char *endDone = nullptr, *endTotal = nullptr;
    const auto d = std::strtoull(done.c_str(), &endDone, 10), t = std::strtoull(total.c_str(), &endTotal, 10);
    if (done.empty() || total.empty() || *endDone || *endTotal) return false;
    progress(std::string(text.substr(0, space)), d, t);
    return true;
  }

  // Called by the component from inside an fmi3 call: it must not throw back across the C ABI.
  static void callback(fmi3InstanceEnvironment env, fmi3Status status, fmi3String category, fmi3String message) {
    try {
      auto* sink = static_cast<LogSink*>(env);
      const std::string_view cat = category ? category : "";
      if (cat == "logProgress" && sink->forwardProgress(message ? message : "")) return;
      sink->messages.push_back({status, std::string(cat), message ? message : ""});
    } catch (...) {
    }
  }
};

FmuInstance::FmuInstance(const FmuLibrary& library, const ModelDescription& md, const Options& options)
    : api_(library.api()), log_(std::make_unique<LogSink>()) {
  log_->instanceName = options.instanceName;
  log_->verbose = options.verbose;
  instance_ = api_.InstantiateCoSimulation(
      options.instanceName.c_str(), md.instantiationToken.c_str(),
      options.resourcePath.empty() ? nullptr : options.resourcePath.c_str(), /*visible=*/false,
      /*loggingOn=*/true, /*eventModeUsed=*/false, /*earlyReturnAllowed=*/false,
      /*requiredIntermediateVariables=*/nullptr, 0, log_.get(), &LogSink::callback, /*intermediateUpdate=*/nullptr);
  if (!instance_) check(fmi3Error, "fmi3InstantiateCoSimulation");
  if (options.progress) {
    log_->progress = options.progress;
    fmi3String categories[] = {"logProgress"};
    // A courtesy: a component without the category refuses it, and then runs without progress.
    if (api_.SetDebugLogging(instance_, fmi3True, 1, categories) != fmi3OK) {
      log_->messages.clear();
      log_->progress = nullptr;
    }
  }
}

FmuInstance::~FmuInstance() {
  // After fmi3Fatal the standard allows no further call, not even fmi3FreeInstance.
  if (instance_ && !fatal_) api_.FreeInstance(instance_);
}

void FmuInstance::check(fmi3Status status, const char* function) {
  std::vector<LogSink::Message> messages = std::exchange(log_->messages, {});
  if (status == fmi3OK || status == fmi3Warning) {
    for (const auto& m : messages)
      if (m.status != fmi3OK || log_->verbose)
        std::cerr << "peristep: " << log_->instanceName << ": " << statusName(m.status) << " [" << m.category
                  << "] " << oneLine(m.text) << '\n';
    return;
  }
  if (status == fmi3Fatal) fatal_ = true;
  std::string text;
  const std::string prefix = std::string(function) + ": ";  // said once is enough
  for (const auto& m : messages) {
    if (m.status == fmi3OK) continue;
    std::string line = oneLine(m.text);
    if (line.starts_with(prefix)) line.erase(0, prefix.size());
    text += (text.empty() ? "" : "; ") + line;
  }
  throw RunError(std::string(function) + " returned " + statusName(status) + ": " +
                 (text.empty() ? "(the component logged no message)" : text));
}

void FmuInstance::enterConfigurationMode() { check(api_.EnterConfigurationMode(instance_), "fmi3EnterConfigurationMode"); }
void FmuInstance::exitConfigurationMode() { check(api_.ExitConfigurationMode(instance_), "fmi3ExitConfigurationMode"); }

void FmuInstance::enterInitializationMode(double startTime, double stopTime) {
  check(api_.EnterInitializationMode(instance_, /*toleranceDefined=*/false, 0.0, startTime, /*stopTimeDefined=*/true,
                                     stopTime),
        "fmi3EnterInitializationMode");
}

void FmuInstance::exitInitializationMode() { check(api_.ExitInitializationMode(instance_), "fmi3ExitInitializationMode"); }

bool FmuInstance::doStep(double time, double stepSize) {
  fmi3Boolean eventHandlingNeeded = false, terminateSimulation = false, earlyReturn = false;
  fmi3Float64 lastSuccessfulTime = time;
  check(api_.DoStep(instance_, time, stepSize, /*noSetFMUStatePriorToCurrentPoint=*/true, &eventHandlingNeeded,
                    &terminateSimulation, &earlyReturn, &lastSuccessfulTime),
        "fmi3DoStep");
  return !terminateSimulation;
}

void FmuInstance::terminate() { check(api_.Terminate(instance_), "fmi3Terminate"); }

void FmuInstance::set(const Variable& v, const Values& values) {
  const fmi3ValueReference vr = v.valueReference;
  const std::size_t n = valueCount(values);
  const auto call = [&](auto* setter, const char* name, const auto& data) {
    check(setter(instance_, &vr, 1, data.data(), n), name);
  };
  switch (v.type) {
    case VarType::Float32: call(api_.SetFloat32, "fmi3SetFloat32", narrow<fmi3Float32>(std::get<0>(values))); break;
    case VarType::Float64: call(api_.SetFloat64, "fmi3SetFloat64", std::get<0>(values)); break;
    case VarType::Int8: call(api_.SetInt8, "fmi3SetInt8", narrow<fmi3Int8>(std::get<1>(values))); break;
    case VarType::Int16: call(api_.SetInt16, "fmi3SetInt16", narrow<fmi3Int16>(std::get<1>(values))); break;
    case VarType::Int32: call(api_.SetInt32, "fmi3SetInt32", narrow<fmi3Int32>(std::get<1>(values))); break;
    case VarType::Int64:
    case VarType::Enumeration: call(api_.SetInt64, "fmi3SetInt64", std::get<1>(values)); break;
    case VarType::UInt8: call(api_.SetUInt8, "fmi3SetUInt8", narrow<fmi3UInt8>(std::get<2>(values))); break;
    case VarType::UInt16: call(api_.SetUInt16, "fmi3SetUInt16", narrow<fmi3UInt16>(std::get<2>(values))); break;
    case VarType::UInt32: call(api_.SetUInt32, "fmi3SetUInt32", narrow<fmi3UInt32>(std::get<2>(values))); break;
    case VarType::UInt64: call(api_.SetUInt64, "fmi3SetUInt64", std::get<2>(values)); break;
    case VarType::Boolean: {
      // std::vector<bool> has no contiguous storage to hand to C.
      const auto& bits = std::get<3>(values);
      std::unique_ptr<fmi3Boolean[]> flags(new fmi3Boolean[n]);
      for (std::size_t i = 0; i < n; ++i) flags[i] = bits[i];
      check(api_.SetBoolean(instance_, &vr, 1, flags.get(), n), "fmi3SetBoolean");
      break;
    }
    default: throw RunError("cannot set " + v.name + ": type " + std::string(toString(v.type)) + " is not supported");
  }
}

Values FmuInstance::get(const Variable& v, std::size_t n) {
  const fmi3ValueReference vr = v.valueReference;
  const auto read = [&]<class C>(auto* getter, const char* name, std::vector<C> buffer) {
    buffer.resize(n);
    check(getter(instance_, &vr, 1, buffer.data(), n), name);
    return buffer;
  };
  switch (v.type) {
    case VarType::Float32: return narrow<double>(read(api_.GetFloat32, "fmi3GetFloat32", std::vector<fmi3Float32>{}));
    case VarType::Float64: return read(api_.GetFloat64, "fmi3GetFloat64", std::vector<fmi3Float64>{});
    case VarType::Int8: return narrow<std::int64_t>(read(api_.GetInt8, "fmi3GetInt8", std::vector<fmi3Int8>{}));
    case VarType::Int16: return narrow<std::int64_t>(read(api_.GetInt16, "fmi3GetInt16", std::vector<fmi3Int16>{}));
    case VarType::Int32: return narrow<std::int64_t>(read(api_.GetInt32, "fmi3GetInt32", std::vector<fmi3Int32>{}));
    case VarType::Int64:
    case VarType::Enumeration: return read(api_.GetInt64, "fmi3GetInt64", std::vector<std::int64_t>{});
    case VarType::UInt8: return narrow<std::uint64_t>(read(api_.GetUInt8, "fmi3GetUInt8", std::vector<fmi3UInt8>{}));
    case VarType::UInt16: return narrow<std::uint64_t>(read(api_.GetUInt16, "fmi3GetUInt16", std::vector<fmi3UInt16>{}));
    case VarType::UInt32: return narrow<std::uint64_t>(read(api_.GetUInt32, "fmi3GetUInt32", std::vector<fmi3UInt32>{}));
    case VarType::UInt64: return read(api_.GetUInt64, "fmi3GetUInt64", std::vector<std::uint64_t>{});
    case VarType::Boolean: {
      std::unique_ptr<fmi3Boolean[]> flags(new fmi3Boolean[n]);
      check(api_.GetBoolean(instance_, &vr, 1, flags.get(), n), "fmi3GetBoolean");
      return std::vector<bool>(flags.get(), flags.get() + n);
    }
    default: throw RunError("cannot read " + v.name + ": type " + std::string(toString(v.type)) + " is not supported");
  }
}

std::vector<double> FmuInstance::getFloat64(const std::vector<std::uint32_t>& valueReferences, std::size_t count) {
  std::vector<double> out(count);
  if (valueReferences.empty()) return out;
  check(api_.GetFloat64(instance_, valueReferences.data(), valueReferences.size(), out.data(), count), "fmi3GetFloat64");
  return out;
}

std::vector<std::uint64_t> FmuInstance::shape(const Variable& v) {
  std::vector<std::uint64_t> extents;
  for (const Dimension& d : v.dimensions) {
    if (d.start) {
      extents.push_back(*d.start);
      continue;
    }
    const fmi3ValueReference vr = *d.valueReference;
    fmi3UInt64 extent = 0;
    check(api_.GetUInt64(instance_, &vr, 1, &extent, 1), "fmi3GetUInt64");
    extents.push_back(extent);
  }
  return extents;
}

}  // namespace peristep::host
