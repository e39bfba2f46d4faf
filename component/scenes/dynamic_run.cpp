#include "scenes/dynamic_run.hpp"

#include <cmath>

#include "core/errors.hpp"

namespace peristep {

DynamicRunResult runDynamicScene(DynamicScene& scene, const DynamicRunOptions& o,
                                 const std::function<void(const TimeIntegrator&, const EnergyRecord&)>& onReport) {
  IntegratorOptions io = o.options;
  if (io.timeStep == 0) io.timeStep = scene.timeStep;
  const double endTime = o.endTime > 0 ? o.endTime : scene.endTime;
  require(endTime > 0 && o.reportInterval > 0, "dynamic run: end time and report interval must be positive");
  auto integrator = makeTimeIntegrator(o.integrator, *scene.problem, io);
  FractureDiagnostics diagnostics(scene);
  DynamicRunResult result;
  const auto report = [&] {
    result.records.push_back(diagnostics.measure(*integrator));
    if (onReport) onReport(*integrator, result.records.back());
  };
  report();
  const auto intervals = static_cast<long>(std::ceil(endTime / o.reportInterval - 1e-9));
  for (long k = 1; k <= intervals; ++k) {
    integrator->advanceTo(std::min(endTime, static_cast<double>(k) * o.reportInterval));
    report();
  }
  result.stats = integrator->stats();
  return result;
}

}  // namespace peristep
