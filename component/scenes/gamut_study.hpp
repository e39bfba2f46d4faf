#pragma once
// Monte Carlo study of the 002 bar: independent realizations (OpenMP over realizations, each with its
// own random stream, so the result does not depend on the thread count), cyclic n' and K' per
// realization, their means with 95% intervals, and optionally the mean monotonic curve.
#include <cstddef>
#include <vector>

#include "models/gamut_bar.hpp"
#include "scenes/cyclic_fit.hpp"
#include "scenes/gamut_loading.hpp"
#include "scenes/mean_interval.hpp"

namespace peristep {

struct GamutStudySpec {
  GamutBarSpec bar;
  int realizations = 30;
  std::size_t firstRealization = 0;  // realization indices first .. first + realizations - 1
  CyclicProtocol protocol;           // empty amplitudes: gamutCyclicProtocol(bar.material)
  bool cyclic = true;
  bool monotonic = false;
};

struct GamutRealization {
  CyclicFit fit;
  CyclicLoops loops;
  MonotonicCurve curve;
  GamutSolverCounters counters;
  int reruns = 0;  // runs repeated without the solver's linear part (LinearRangeExceeded)
};

struct GamutStudy {
  std::vector<GamutRealization> runs;
  MeanInterval exponent, coefficient;  // n', K' [Pa] (cyclic studies)
  // Mean monotonic curve: the force levels are common to all realizations, the strain is averaged
  // over them, up to the last step every realization reached.
  std::vector<double> meanStress, meanStrain;
  GamutSolverCounters counters;  // summed over the realizations
};

GamutStudy runGamutStudy(const GamutStudySpec& spec);

}  // namespace peristep
