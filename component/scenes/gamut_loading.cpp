#include "scenes/gamut_loading.hpp"

#include <cmath>

#include "core/errors.hpp"

namespace peristep {

MonotonicCurve monotonicLoading(GamutBarSolver& solver, double failureStrain, double firstForce, double growth,
                                std::size_t maxSteps) {
  require(firstForce > 0 && growth > 0, "monotonic loading: the first force and the growth must be positive");
  MonotonicCurve curve;
  double force = firstForce;
  for (std::size_t s = 0; s < maxSteps; ++s, force *= 1 + growth) {
    GamutBarOutput out;
    try {
      out = solver.step(force);
    } catch (const LinearRangeExceeded&) {
      throw;
    } catch (const SolverFailure& e) {
      curve.stopped = e.what();
      break;
    }
    curve.stress.push_back(out.stress);
    curve.strain.push_back(out.strain);
    curve.brokenBonds.push_back(out.brokenBonds);
    if (out.strain > failureStrain) break;
  }
  return curve;
}

CyclicProtocol gamutCyclicProtocol(const RambergOsgood& material, int amplitudes, int stepsPerHalfCycle) {
  require(amplitudes >= 2 && stepsPerHalfCycle >= 1, "cyclic protocol: needs >= 2 amplitudes and >= 1 step per half cycle");
  CyclicProtocol protocol;
  protocol.stepsPerHalfCycle = stepsPerHalfCycle;
  for (int k = 0; k < amplitudes; ++k)
    protocol.amplitudes.push_back(material.yieldStress +
                                  (material.failureStress - material.yieldStress) * k / (amplitudes - 1));
  return protocol;
}

CyclicLoops cyclicLoading(GamutBarSolver& solver, const CyclicProtocol& protocol, double area) {
  CyclicLoops loops;
  const GamutBarOutput first = solver.step(0.01);
  loops.modulus = first.stress / first.strain;
  auto rampTo = [&](double force) {
    const double from = solver.force();
    GamutBarOutput out;
    for (int s = 1; s <= protocol.stepsPerHalfCycle; ++s)
      out = solver.step(from + (force - from) * s / protocol.stepsPerHalfCycle);
    return out.strain;
  };
  double peak = 0;
  for (double amplitude : protocol.amplitudes) {
    const double force = amplitude * area;
    peak = rampTo(force);
    const double valley = rampTo(-force);
    // Masing loops close: the half cycle back to +F_a would end at `peak` again (checked below at the
    // largest amplitude), so the loop is -F_a .. +F_a with the strains of these two visits.
    const double strainAmplitude = 0.5 * (peak - valley);
    loops.stressAmplitude.push_back(amplitude);
    loops.strainAmplitude.push_back(strainAmplitude);
    loops.plasticStrainAmplitude.push_back(strainAmplitude - amplitude / loops.modulus);
  }
  loops.closure = std::abs(rampTo(protocol.amplitudes.back() * area) - peak);
  return loops;
}

}  // namespace peristep
