#include "scenes/gamut_study.hpp"

#include <algorithm>
#include <limits>

#include "core/errors.hpp"
#include "core/parallel_errors.hpp"

namespace peristep {

GamutStudy runGamutStudy(const GamutStudySpec& spec) {
  require(spec.realizations >= 2, "gamut study: needs two or more realizations");
  const CyclicProtocol protocol =
      spec.protocol.amplitudes.empty() ? gamutCyclicProtocol(spec.bar.material, 6, spec.protocol.stepsPerHalfCycle) : spec.protocol;
  GamutStudy study;
  study.runs.resize(static_cast<std::size_t>(spec.realizations));
  ParallelErrors errors;
#pragma omp parallel for schedule(dynamic)
  for (int r = 0; r < spec.realizations; ++r)
    errors.capture([&] {
      GamutRealization& run = study.runs[static_cast<std::size_t>(r)];
      const GamutBar bar(spec.bar, spec.firstRealization + static_cast<std::size_t>(r));
      // A realization whose local strains pass the solver's bound for the far elements (a strongly
      // localizing one) runs again with every element free to slip.
      auto withFallback = [&](auto&& body) {
        try {
          body(0.0);
        } catch (const LinearRangeExceeded&) {
          ++run.reruns;
          body(std::numeric_limits<double>::infinity());
        }
      };
      if (spec.cyclic)
        withFallback([&](double linearStrain) {
          GamutBarSolver solver(bar, linearStrain);
          run.loops = cyclicLoading(solver, protocol, spec.bar.area);
          run.fit = fitCyclicCurve(run.loops.stressAmplitude, run.loops.plasticStrainAmplitude);
          run.counters += solver.counters();
        });
      if (spec.monotonic)
        withFallback([&](double linearStrain) {
          GamutBarSolver solver(bar, linearStrain);
          run.curve = monotonicLoading(solver, spec.bar.material.failureStrain);
          run.counters += solver.counters();
        });
    });
  errors.rethrow();

  for (const GamutRealization& run : study.runs) study.counters += run.counters;
  if (spec.cyclic) {
    std::vector<double> n, k;
    for (const GamutRealization& run : study.runs) {
      n.push_back(run.fit.exponent);
      k.push_back(run.fit.coefficient);
    }
    study.exponent = meanInterval(n);
    study.coefficient = meanInterval(k);
  }
  if (spec.monotonic) {
    std::size_t steps = study.runs.front().curve.strain.size();
    for (const GamutRealization& run : study.runs) steps = std::min(steps, run.curve.strain.size());
    study.meanStress.assign(study.runs.front().curve.stress.begin(), study.runs.front().curve.stress.begin() + steps);
    study.meanStrain.assign(steps, 0.0);
    for (const GamutRealization& run : study.runs)
      for (std::size_t s = 0; s < steps; ++s) study.meanStrain[s] += run.curve.strain[s] / spec.realizations;
  }
  return study;
}

}  // namespace peristep
