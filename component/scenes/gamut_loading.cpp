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

std::vector<double> cyclicForces(const CyclicProtocol& protocol, double area) {
  std::vector<double> forces{0.01};
  // Each ramp starts where the last one ended: the force the solver holds after its last step.
  auto rampTo = [&](double force) {
    const double from = forces.back();
    for (int s = 1; s <= protocol.stepsPerHalfCycle; ++s)
      forces.push_back(from + (force - from) * s / protocol.stepsPerHalfCycle);
  };
  for (double amplitude : protocol.amplitudes) {
    rampTo(amplitude * area);
    rampTo(-amplitude * area);
  }
  rampTo(protocol.amplitudes.back() * area);  // back to +F_a once more: does the last loop close?
  return forces;
}

CyclicLoops cyclicLoops(const CyclicProtocol& protocol, double area, std::span<const double> strains) {
  const std::size_t perHalf = static_cast<std::size_t>(protocol.stepsPerHalfCycle);
  const std::size_t levels = protocol.amplitudes.size();
  require(strains.size() == 1 + (2 * levels + 1) * perHalf, "cyclic loops: one strain per step of the protocol");
  CyclicLoops loops;
  loops.modulus = 0.01 / area / strains[0];
  double peak = 0;
  for (std::size_t a = 0; a < levels; ++a) {
    const double amplitude = protocol.amplitudes[a];
    peak = strains[(2 * a + 1) * perHalf];
    const double valley = strains[(2 * a + 2) * perHalf];
    // Masing loops close: the half cycle back to +F_a would end at `peak` again (checked below at the
    // largest amplitude), so the loop is -F_a .. +F_a with the strains of these two visits.
    const double strainAmplitude = 0.5 * (peak - valley);
    loops.stressAmplitude.push_back(amplitude);
    loops.strainAmplitude.push_back(strainAmplitude);
    loops.plasticStrainAmplitude.push_back(strainAmplitude - amplitude / loops.modulus);
  }
  loops.closure = std::abs(strains.back() - peak);
  return loops;
}

CyclicLoops cyclicLoading(GamutBarSolver& solver, const CyclicProtocol& protocol, double area) {
  std::vector<double> strains;
  for (double force : cyclicForces(protocol, area)) strains.push_back(solver.step(force).strain);
  return cyclicLoops(protocol, area, strains);
}

}  // namespace peristep
