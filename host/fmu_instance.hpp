#pragma once
// One co-simulation instance of a loaded FMU, with RAII (fmi3FreeInstance in the destructor) and
// one rule for every call: a status other than fmi3OK/fmi3Warning throws RunError carrying what the
// component logged, so no failure passes unnoticed and the user sees the component's own reason.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "fmu_loader.hpp"
#include "model_description.hpp"
#include "variable_values.hpp"

namespace peristep::host {

class FmuInstance {
 public:
  struct Options {
    std::string instanceName = "peristep";
    std::string resourcePath;  // empty: passed as NULL
    bool verbose = false;      // echo every logged message, not only warnings
    // Receives the component's 'progress: <phase> <done>/<total>' messages (category logProgress) while a
    // call runs (total 0: open-ended, e.g. sub-iterations); set, it switches that category on.
    std::function<void(const std::string& phase, std::uint64_t done, std::uint64_t total)> progress;
  };

  FmuInstance(const FmuLibrary& library, const ModelDescription& md, const Options& options);
  ~FmuInstance();
  FmuInstance(const FmuInstance&) = delete;
  FmuInstance& operator=(const FmuInstance&) = delete;

  void enterConfigurationMode();
  void exitConfigurationMode();
  void enterInitializationMode(double startTime, double stopTime);
  void exitInitializationMode();
  // Returns false when the component asks the importer to stop (terminateSimulation).
  bool doStep(double time, double stepSize);
  void terminate();

  void set(const Variable& v, const Values& values);
  Values get(const Variable& v, std::size_t count);
  // Several scalar Float64 variables in one call.
  std::vector<double> getFloat64(const std::vector<std::uint32_t>& valueReferences, std::size_t count);
  // Extent of each dimension: a fixed start, or the current value of the structural parameter.
  std::vector<std::uint64_t> shape(const Variable& v);

 private:
  struct LogSink;
  void check(fmi3Status status, const char* function);

  const Fmi3Api& api_;
  std::unique_ptr<LogSink> log_;
  fmi3Instance instance_ = nullptr;
  bool fatal_ = false;
};

}  // namespace peristep::host
