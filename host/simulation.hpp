#pragma once
// One co-simulation of a scene through the C ABI. Construction instantiates and initializes:
// structural parameters are set in Configuration Mode, the other parameters in Instantiated, as
// FMI 3.0 allows; then each increment of the load schedule is one fmi3DoStep.
#include <string>
#include <vector>

#include "fmu_instance.hpp"
#include "load_schedule.hpp"
#include "result_layout.hpp"
#include "scene_file.hpp"

namespace peristep::host {

// Structural parameters in Configuration Mode, the others in Instantiated, as FMI 3.0 allows.
void setSceneParameters(FmuInstance& instance, const Scene& scene);

class Simulation {
 public:
  Simulation(const FmuLibrary& library, const ModelDescription& md, const Scene& scene, const FmuInstance::Options& options);

  const std::vector<Increment>& schedule() const { return schedule_; }
  // The grid, the parameters as the component holds them after initialization, and the outputs
  // recorded per step (Float64 outputs: scalars as time series, arrays as fields).
  ResultLayout layout();

  // Sets the ramped input, calls fmi3DoStep and reads every recorded output.
  StepValues step(const Increment& increment);
  // False once the component has asked to stop; the loop must not step again.
  bool mayContinue() const { return mayContinue_; }
  double readScalar(const std::string& name);
  // A scalar integer variable (Int8..Int64); throws RunError when the model has none of that name.
  std::int64_t readInteger(const std::string& name);
  void terminate() { instance_.terminate(); }

 private:
  const ModelDescription& md_;
  const Scene& scene_;
  FmuInstance instance_;
  std::vector<Increment> schedule_;
  std::vector<const Variable*> scalars_, fields_;
  std::vector<std::uint32_t> scalarRefs_;
  std::vector<std::uint64_t> fieldSizes_;
  bool mayContinue_ = true;
};

}  // namespace peristep::host
