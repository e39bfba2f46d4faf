// The dynamic scenes of 001 Sec. 6 through the C ABI only: fmi3DoStep integrates each communication
// step with the chosen time integrator, the energy outputs balance the work of the loads, loadFactor
// scales the loads, FMU states checkpoint a run, and bad integrator settings are refused with one message.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "fmi_abi_support.hpp"

using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

// The Plexiglass square of 001 Sec. 6.1 at its coarsest resolution: eps = 8 mm, h = eps/2 (25 x 25
// material nodes spanning 0.096 m, the cells 0.1 m; with the two collars 725 nodes).
constexpr std::uint64_t kSide = 25;
constexpr std::size_t kNodes = kSide * kSide;
constexpr double kStep = 2e-6;  // communication step [s]

void setUpPlexiglass(Session& s, std::int64_t integrator, double internalStep = 0) {
  REQUIRE(s.configure(kSide, kSide) == fmi3OK);
  REQUIRE(s.setInt64(PERISTEP_VR_SCENE, PERISTEP_SCENE_PLEXIGLASS_CRACK) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_LX, {0.096}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_LY, {0.096}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_DELTA_OVER_H, {2.0}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_POISSON_RATIO, {0.25}) == fmi3OK);
  REQUIRE(s.setInt64(PERISTEP_VR_TIME_INTEGRATOR, integrator) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_INTERNAL_TIME_STEP, {internalStep}) == fmi3OK);
}

struct Energies {
  double kinetic, elastic, work, fracture, crack, evaluations;
};

Energies energies(Session& s) {
  const fmi3ValueReference vr[] = {PERISTEP_VR_KINETIC_ENERGY, PERISTEP_VR_STRAIN_ENERGY,
                                   PERISTEP_VR_EXTERNAL_WORK,  PERISTEP_VR_FRACTURE_ENERGY,
                                   PERISTEP_VR_CRACK_LENGTH,   PERISTEP_VR_FORCE_EVALUATIONS};
  double v[6] = {};
  REQUIRE(s.fmu.fmi3GetFloat64(s.instance, vr, 6, v, 6) == fmi3OK);
  return {v[0], v[1], v[2], v[3], v[4], v[5]};
}

// Everything an importer reads after a step: ux, uy, damage, the scalar outputs and the time.
std::vector<double> outputs(Session& s) {
  std::vector<double> row = s.getFloat64(PERISTEP_VR_UX, kNodes);
  for (const fmi3ValueReference vr : {PERISTEP_VR_UY, PERISTEP_VR_DAMAGE}) {
    const auto f = s.getFloat64(vr, kNodes);
    row.insert(row.end(), f.begin(), f.end());
  }
  const Energies e = energies(s);
  row.insert(row.end(), {e.kinetic, e.elastic, e.work, e.fracture, e.crack, s.getFloat64(PERISTEP_VR_TIME).at(0)});
  REQUIRE(row.size() == 3 * kNodes + 6);
  return row;
}

std::vector<std::vector<double>> continueRun(Session& s, double t, int steps) {
  std::vector<std::vector<double>> rows;
  for (int k = 0; k < steps; ++k) {
    REQUIRE(s.step(t + k * kStep, kStep) == fmi3OK);
    rows.push_back(outputs(s));
  }
  return rows;
}

double maxRelativeDifference(const std::vector<double>& a, const std::vector<double>& b) {
  REQUIRE(a.size() == b.size());
  double scale = 0, diff = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    scale = std::max(scale, std::abs(a[i]));
    diff = std::max(diff, std::abs(a[i] - b[i]));
  }
  return diff / scale;
}

}  // namespace

TEST_CASE("the Plexiglass crack runs through fmi3DoStep and its energies balance the work of the loads",
          "[abi][dynamics]") {
  Session s;
  setUpPlexiglass(s, PERISTEP_INTEGRATOR_CENTRAL_DIFFERENCE);
  REQUIRE(s.initialize(0, 34e-6) == fmi3OK);
  const Energies e0 = energies(s);
  CHECK(e0.kinetic > 0);  // the strips start at 1 m/s
  CHECK(e0.elastic == 0);
  CHECK(e0.work == 0);
  // Central difference at the scene's step 0.004 us: 500 force evaluations per 2 us.
  double previousWork = 0;
  for (int k = 0; k < 12; ++k) {
    REQUIRE(s.step(k * kStep, kStep) == fmi3OK);
    const Energies e = energies(s);
    CHECK(e.evaluations == Approx(1 + 500.0 * (k + 1)).margin(k + 1));
    CHECK(e.work > previousWork);
    // No damping and no other loads: kinetic + elastic - work keeps its initial value.
    CHECK(std::abs(e.kinetic + e.elastic - e.work - e0.kinetic) <= 1e-3 * e.work);
    CHECK(e.fracture <= e.elastic);  // the crack zone's energy is part of the elastic energy
    previousWork = e.work;
  }
  CHECK(s.getFloat64(PERISTEP_VR_TIME).at(0) == Approx(24e-6));
  // The strips pull the bottom edge apart: left of the pre-crack ux < 0, right of it ux > 0.
  const auto ux = s.getFloat64(PERISTEP_VR_UX, kNodes);
  REQUIRE(ux.size() == kNodes);
  CHECK(ux[0] < 0);
  CHECK(ux[kSide - 1] > 0);
  // The crack has started to grow from the pre-crack tip by 24 us (001 Fig. 5), and Z > 1 on it.
  const Energies e = energies(s);
  CHECK(e.crack > 0);
  CHECK(e.fracture > 0);
  const auto Z = s.getFloat64(PERISTEP_VR_DAMAGE, kNodes);
  CHECK(*std::max_element(Z.begin(), Z.end()) > 1.0);
  CHECK(s.log.errors() == 0);
}

TEST_CASE("the time integrator is the scene's choice", "[abi][dynamics]") {
  Session cd, erk, bdf;
  setUpPlexiglass(cd, PERISTEP_INTEGRATOR_CENTRAL_DIFFERENCE);
  setUpPlexiglass(erk, PERISTEP_INTEGRATOR_ARKODE_ERK);
  setUpPlexiglass(bdf, PERISTEP_INTEGRATOR_CVODE_BDF);
  for (Session* s : {&cd, &erk, &bdf}) REQUIRE(s->initialize(0, 34e-6) == fmi3OK);
  const double kinetic0 = energies(cd).kinetic;
  for (Session* s : {&cd, &erk, &bdf}) REQUIRE(s->step(0, kStep) == fmi3OK);
  const double nCd = energies(cd).evaluations, nErk = energies(erk).evaluations, nBdf = energies(bdf).evaluations;
  CHECK(nCd == Approx(501).margin(1));
  // Different methods do different amounts of work over the same 2 us ...
  CHECK(nErk != nCd);
  CHECK(nBdf != nCd);
  CHECK(nBdf != nErk);
  // ... and reach the same displacements (tolerances 1e-6 relative against a scheme of order 2).
  const auto uCd = cd.getFloat64(PERISTEP_VR_UX, kNodes);
  CHECK(maxRelativeDifference(erk.getFloat64(PERISTEP_VR_UX, kNodes), uCd) < 2e-3);
  CHECK(maxRelativeDifference(bdf.getFloat64(PERISTEP_VR_UX, kNodes), uCd) < 2e-3);
  for (Session* s : {&erk, &bdf}) {
    const Energies e = energies(*s);
    CHECK(std::abs(e.kinetic + e.elastic - e.work - kinetic0) <= 1e-3 * e.work);
  }
}

TEST_CASE("loadFactor scales the pull velocity from the communication point on", "[abi][dynamics]") {
  Session full, half;
  setUpPlexiglass(full, PERISTEP_INTEGRATOR_CENTRAL_DIFFERENCE);
  setUpPlexiglass(half, PERISTEP_INTEGRATOR_CENTRAL_DIFFERENCE);
  REQUIRE(half.setFloat64(PERISTEP_VR_LOAD_FACTOR, {0.5}) == fmi3OK);
  REQUIRE(full.initialize(0, 34e-6) == fmi3OK);
  REQUIRE(half.initialize(0, 34e-6) == fmi3OK);
  REQUIRE(full.step(0, kStep) == fmi3OK);
  REQUIRE(half.step(0, kStep) == fmi3OK);
  // Small strains at 2 us: the response is nearly linear in the load (the tensile force of 001:(14)
  // softens only near the strips' corners and the pre-crack tip), so displacements about halve.
  const auto uFull = full.getFloat64(PERISTEP_VR_UX, kNodes), uHalf = half.getFloat64(PERISTEP_VR_UX, kNodes);
  std::vector<double> halved = uFull;
  for (double& u : halved) u *= 0.5;
  CHECK(maxRelativeDifference(uHalf, halved) < 2e-2);
  CHECK(energies(half).work == Approx(0.25 * energies(full).work).epsilon(2e-2));

  SECTION("loadFactor 0 holds the strips: no more work is done") {
    REQUIRE(full.setFloat64(PERISTEP_VR_LOAD_FACTOR, {0.0}) == fmi3OK);
    REQUIRE(full.step(kStep, kStep) == fmi3OK);
    const Energies a = energies(full);
    REQUIRE(full.step(2 * kStep, kStep) == fmi3OK);
    const Energies b = energies(full);
    CHECK(b.work == a.work);
    CHECK(b.kinetic + b.elastic == Approx(a.kinetic + a.elastic).epsilon(1e-4));
  }
}

TEST_CASE("an FMU state checkpoints a dynamic run", "[abi][dynamics][fmustate]") {
  SECTION("central difference continues bit for bit, in the same and in another instance") {
    Session s;
    setUpPlexiglass(s, PERISTEP_INTEGRATOR_CENTRAL_DIFFERENCE);
    REQUIRE(s.initialize(0, 34e-6) == fmi3OK);
    REQUIRE(s.setFloat64(PERISTEP_VR_LOAD_FACTOR, {0.8}) == fmi3OK);
    continueRun(s, 0, 2);
    fmi3FMUState state = nullptr;
    REQUIRE(s.fmu.fmi3GetFMUState(s.instance, &state) == fmi3OK);
    const auto reference = continueRun(s, 2 * kStep, 2);
    REQUIRE(s.fmu.fmi3SetFMUState(s.instance, state) == fmi3OK);
    CHECK(continueRun(s, 2 * kStep, 2) == reference);

    std::size_t size = 0;
    REQUIRE(s.fmu.fmi3SerializedFMUStateSize(s.instance, state, &size) == fmi3OK);
    std::vector<fmi3Byte> bytes(size);
    REQUIRE(s.fmu.fmi3SerializeFMUState(s.instance, state, bytes.data(), size) == fmi3OK);
    Session other;
    REQUIRE(other.configure(kSide, kSide) == fmi3OK);
    fmi3FMUState copy = nullptr;
    REQUIRE(other.fmu.fmi3DeserializeFMUState(other.instance, bytes.data(), size, &copy) == fmi3OK);
    REQUIRE(other.fmu.fmi3SetFMUState(other.instance, copy) == fmi3OK);
    CHECK(continueRun(other, 2 * kStep, 2) == reference);
    REQUIRE(other.fmu.fmi3FreeFMUState(other.instance, &copy) == fmi3OK);
    REQUIRE(s.fmu.fmi3FreeFMUState(s.instance, &state) == fmi3OK);
    CHECK(s.log.errors() == 0);
    CHECK(other.log.errors() == 0);
  }
  SECTION("ARKODE restarts with a fresh step-size history and agrees to its tolerance") {
    Session s;
    setUpPlexiglass(s, PERISTEP_INTEGRATOR_ARKODE_ERK);
    REQUIRE(s.initialize(0, 34e-6) == fmi3OK);
    continueRun(s, 0, 1);
    fmi3FMUState state = nullptr;
    REQUIRE(s.fmu.fmi3GetFMUState(s.instance, &state) == fmi3OK);
    const auto reference = continueRun(s, kStep, 1);
    REQUIRE(s.fmu.fmi3SetFMUState(s.instance, state) == fmi3OK);
    const auto again = continueRun(s, kStep, 1);
    CHECK(maxRelativeDifference(again[0], reference[0]) < 1e-4);
    CHECK(again[0].back() == reference[0].back());  // the time
    REQUIRE(s.fmu.fmi3FreeFMUState(s.instance, &state) == fmi3OK);
  }
}

TEST_CASE("bad integrator settings are refused with one message", "[abi][dynamics][arguments]") {
  Session s;
  SECTION("an integrator that does not exist") {
    CHECK(s.setInt64(PERISTEP_VR_TIME_INTEGRATOR, 4) == fmi3Error);
    REQUIRE(s.log.errors() == 1);
    CHECK_THAT(s.log.records.back().message,
               StartsWith("fmi3SetInt64: timeIntegrator (vr 60) = 4 is not a value of PeriStep.TimeIntegrator (1 "
                          "centralDifference, 2 arkodeErk, 3 cvodeBdf)"));
  }
  SECTION("a central difference step above the stability limit") {
    setUpPlexiglass(s, PERISTEP_INTEGRATOR_CENTRAL_DIFFERENCE, 1e-5);
    REQUIRE(s.fmu.fmi3EnterInitializationMode(s.instance, fmi3False, 0, 0, fmi3False, 0) == fmi3OK);
    CHECK(s.fmu.fmi3ExitInitializationMode(s.instance) == fmi3Error);
    REQUIRE(s.log.errors() == 1);
    const std::string& m = s.log.records.back().message;
    CHECK_THAT(m, StartsWith("fmi3ExitInitializationMode: internalTimeStep = 1e-05 s"));
    CHECK_THAT(m, Contains("exceeds the stability limit"));
  }
  SECTION("a grid that is not uniform") {
    setUpPlexiglass(s, PERISTEP_INTEGRATOR_CENTRAL_DIFFERENCE);
    REQUIRE(s.setFloat64(PERISTEP_VR_LY, {0.2}) == fmi3OK);
    CHECK(s.initialize(0, 1) == fmi3Error);
    REQUIRE(s.log.errors() == 1);
    CHECK_THAT(s.log.records.back().message, Contains("grid spacing must be uniform: Lx/(nx-1)"));
  }
}

TEST_CASE("the bending beam with two notches is loaded symmetrically", "[abi][dynamics]") {
  // 001 Sec. 6.2's beam (0.25 x 0.05 m of cells, the points spanning h less) at h = 3.125 mm (no node on a pre-crack line, no bond through a tip), eps = 3 h; a
  // larger internal step than the paper's keeps the test short (the stability limit is far above it).
  constexpr std::uint64_t nx = 80, ny = 16;
  Session s;
  REQUIRE(s.configure(nx, ny) == fmi3OK);
  REQUIRE(s.setInt64(PERISTEP_VR_SCENE, PERISTEP_SCENE_BENDING_TWO_NOTCHES) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_LX, {0.25 - 3.125e-3}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_LY, {0.05 - 3.125e-3}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_DELTA_OVER_H, {3.0}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_POISSON_RATIO, {0.25}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_INTERNAL_TIME_STEP, {0.05e-6}) == fmi3OK);
  REQUIRE(s.initialize(0, 350e-6) == fmi3OK);
  for (int k = 0; k < 2; ++k) REQUIRE(s.step(k * 10e-6, 10e-6) == fmi3OK);
  const auto uy = s.getFloat64(PERISTEP_VR_UY, nx * ny);
  REQUIRE(uy.size() == nx * ny);
  const std::size_t top = (ny - 1) * nx;
  CHECK(uy[top + nx / 2] < 0);  // the load pushes the middle of the top edge down
  double asymmetry = 0;
  for (std::size_t i = 0; i < nx; ++i) asymmetry = std::max(asymmetry, std::abs(uy[top + i] - uy[top + nx - 1 - i]));
  INFO("uy mid " << uy[top + nx / 2] << " min " << *std::min_element(uy.begin(), uy.end()));
  CHECK(asymmetry <= 1e-9 * std::abs(uy[top + nx / 2]));
  const Energies e = energies(s);
  CHECK(e.work > 0);
  CHECK(std::abs(e.kinetic + e.elastic - e.work) <= 1e-3 * e.work);
}
