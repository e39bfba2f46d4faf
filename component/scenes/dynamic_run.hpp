#pragma once
// Run a dynamic scene with any time integrator, recording the energy bookkeeping at fixed intervals.
#include <functional>
#include <string>
#include <vector>

#include "scenes/fracture_diagnostics.hpp"
#include "solvers/time_integrator_kind.hpp"

namespace peristep {

struct DynamicRunOptions {
  TimeIntegratorKind integrator = TimeIntegratorKind::CentralDifference;
  IntegratorOptions options;     // options.timeStep defaults to the scene's when left at 0
  double endTime = 0;            // 0: the scene's
  double reportInterval = 2e-6;  // [s]
};

struct DynamicRunResult {
  std::vector<EnergyRecord> records;  // at t = 0, every reportInterval, and at the end
  IntegratorStats stats;
};

// onReport (optional) sees the integrator and the record at every report time, e.g. to keep snapshots.
DynamicRunResult runDynamicScene(DynamicScene& scene, const DynamicRunOptions& options,
                                 const std::function<void(const TimeIntegrator&, const EnergyRecord&)>& onReport = {});

}  // namespace peristep
