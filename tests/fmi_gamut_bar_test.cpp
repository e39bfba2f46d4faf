// The 1D deformation-gamut bar of 002 as the FMU's scene gamutBar: through the C ABI, one realization's
// cyclic n' and K' are those runGamutStudy computes for it (the same forces, solver and fit: equal, not
// close); a restored FMU state continues bit for bit; bad parameters and inputs are refused with fmi3Error
// and one message. Bars of 40 bonds: each protocol takes well under a second.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "fmi_refusal.hpp"
#include "scenes/gamut_study.hpp"

namespace {

constexpr std::uint64_t kBonds = 40;
constexpr std::size_t kProtocolSteps = 53;  // as the scene's description and scenes/gamut_bar.toml say

void setUpBar(Session& s, std::uint64_t realization, std::int64_t protocol) {
  REQUIRE(s.configure(2, 2, 1) == fmi3OK);
  REQUIRE(s.setInt64(PERISTEP_VR_SCENE, PERISTEP_SCENE_GAMUT_BAR) == fmi3OK);
  REQUIRE(s.setUInt64(PERISTEP_VR_GAMUT_BONDS, kBonds) == fmi3OK);
  REQUIRE(s.setUInt64(PERISTEP_VR_SEED, realization) == fmi3OK);
  REQUIRE(s.setInt64(PERISTEP_VR_GAMUT_PROTOCOL, protocol) == fmi3OK);
}

// barStress, barStrain, brokenBonds, n', K' after each of `steps` steps from step `first`; a monotonic bar
// is pulled to loadFactor 0.1, 0.2, ... (a cyclic one ignores it).
std::vector<std::vector<double>> continueRun(Session& s, std::size_t first, std::size_t steps) {
  std::vector<std::vector<double>> rows;
  for (std::size_t k = first; k < first + steps; ++k) {
    REQUIRE(s.setFloat64(PERISTEP_VR_LOAD_FACTOR, {0.1 * static_cast<double>(k + 1)}) == fmi3OK);
    REQUIRE(s.step(static_cast<double>(k), 1.0) == fmi3OK);
    std::vector<double> row;
    for (fmi3ValueReference vr : {PERISTEP_VR_BAR_STRESS, PERISTEP_VR_BAR_STRAIN, PERISTEP_VR_BROKEN_BONDS,
                                  PERISTEP_VR_CYCLIC_EXPONENT, PERISTEP_VR_CYCLIC_COEFFICIENT})
      row.push_back(s.getFloat64(vr).at(0));
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace

TEST_CASE("gamutBar: the cyclic protocol gives runGamutStudy's n' and K' for the same realization",
          "[abi][gamut]") {
  using namespace peristep;
  for (const std::uint64_t realization : {3, 7}) {
    INFO("realization " << realization);
    Session s;
    setUpBar(s, realization, PERISTEP_GAMUT_CYCLIC);
    REQUIRE(s.initialize(0, 100) == fmi3OK);
    const auto rows = continueRun(s, 0, kProtocolSteps);
    for (std::size_t k = 0; k + 1 < kProtocolSteps; ++k) CHECK(rows[k][3] == 0.0);  // n' only at the end
    // The protocol ends at +sigma_f of Material 1 after closing the last loop.
    CHECK(rows.back()[0] == Approx(gamutMaterial1().failureStress).epsilon(1e-12));

    GamutStudySpec spec;  // the study bench/gamut_bar runs, at 40 bonds, realizations r and r + 1
    spec.bar.bonds = static_cast<int>(kBonds);
    spec.realizations = 2;
    spec.firstRealization = realization;
    const GamutStudy study = runGamutStudy(spec);
    CHECK(rows.back()[3] == study.runs[0].fit.exponent);
    CHECK(rows.back()[4] == study.runs[0].fit.coefficient);
    CHECK(study.runs[0].fit.exponent > 0.0);
    // More steps hold the finished bar.
    CHECK(continueRun(s, kProtocolSteps, 2) == std::vector<std::vector<double>>(2, rows.back()));
    CHECK(s.log.errors() == 0);
  }
  // The step count the scene documents.
  CHECK(cyclicForces(gamutCyclicProtocol(gamutMaterial1()), 1e-4).size() == kProtocolSteps);
}

TEST_CASE("gamutBar: a restored FMU state continues bit for bit", "[abi][gamut][fmustate]") {
  for (const std::int64_t protocol : {PERISTEP_GAMUT_CYCLIC, PERISTEP_GAMUT_MONOTONIC}) {
    INFO("protocol " << protocol);
    Session s;
    setUpBar(s, 5, protocol);
    REQUIRE(s.setFloat64(PERISTEP_VR_SCATTER_DENOMINATOR, {5.0}) == fmi3OK);
    REQUIRE(s.setInt64(PERISTEP_VR_GAMUT_GRID, PERISTEP_GAMUT_GRID_STOCHASTIC) == fmi3OK);
    REQUIRE(s.setFloat64(PERISTEP_VR_LOAD_FACTOR, {0.0}) == fmi3OK);
    REQUIRE(s.initialize(0, 100) == fmi3OK);
    // Monotonic: 9 steps to 0.9 sigma_f, then on to 1.05 sigma_f; cyclic: into the fourth amplitude's loop.
    const std::size_t before = protocol == PERISTEP_GAMUT_CYCLIC ? 30 : 9;
    const std::size_t after = protocol == PERISTEP_GAMUT_CYCLIC ? kProtocolSteps - before : 2;
    continueRun(s, 0, before);
    fmi3FMUState state = nullptr;
    REQUIRE(s.fmu.fmi3GetFMUState(s.instance, &state) == fmi3OK);
    const auto reference = continueRun(s, before, after);
    CHECK(reference.back()[2] > 0);  // elements slip: the state holds an inelastic bar

    REQUIRE(s.fmu.fmi3SetFMUState(s.instance, state) == fmi3OK);
    CHECK(continueRun(s, before, after) == reference);

    Session other;  // another instance of the default scene
    const auto bytes = s.serialize(state);
    REQUIRE(!bytes.empty());
    fmi3FMUState copy = nullptr;
    REQUIRE(other.fmu.fmi3DeserializeFMUState(other.instance, bytes.data(), bytes.size(), &copy) == fmi3OK);
    REQUIRE(other.fmu.fmi3SetFMUState(other.instance, copy) == fmi3OK);
    CHECK(continueRun(other, before, after) == reference);
    REQUIRE(other.fmu.fmi3FreeFMUState(other.instance, &copy) == fmi3OK);
    REQUIRE(s.fmu.fmi3FreeFMUState(s.instance, &state) == fmi3OK);
    CHECK(s.log.errors() == 0);
    CHECK(other.log.errors() == 0);
  }
}

TEST_CASE("gamutBar: bad parameters and inputs are refused with one message", "[abi][gamut]") {
  Session s;
  setUpBar(s, 0, PERISTEP_GAMUT_MONOTONIC);
  SECTION("material 3") {
    requireRefused(s, "fmi3SetInt64", "gamutMaterial (vr 110) = 3 is not a value of PeriStep.GamutMaterial",
                   [&] { return s.setInt64(PERISTEP_VR_GAMUT_MATERIAL, 3); });
  }
  SECTION("one bond, or none") {
    for (const std::uint64_t bonds : {1, 0}) {
      Session t;
      requireRefused(t, "fmi3SetUInt64", "gamutBonds (vr 112) must lie in [4, 20000], got " + std::to_string(bonds),
                     [&] { return t.setUInt64(PERISTEP_VR_GAMUT_BONDS, bonds); });
    }
  }
  SECTION("a negative or zero scatter denominator, a Weibull shape <= 0") {
    requireRefused(s, "fmi3SetFloat64", "scatterDenominator (vr 113) must lie in",
                   [&] { return s.setFloat64(PERISTEP_VR_SCATTER_DENOMINATOR, {-10.0}); });
    Session t;
    requireRefused(t, "fmi3SetFloat64", "weibullShape (vr 114) must lie in",
                   [&] { return t.setFloat64(PERISTEP_VR_WEIBULL_SHAPE, {0.0}); });
  }
  SECTION("a NaN load") {
    REQUIRE(s.initialize(0, 10) == fmi3OK);
    requireRefused(s, "fmi3SetFloat64", "loadFactor (vr 30) must be finite",
                   [&] { return s.setFloat64(PERISTEP_VR_LOAD_FACTOR, {std::numeric_limits<double>::quiet_NaN()}); });
  }
  SECTION("a bar beyond the set-up limits (dense n x n tangent)") {
    REQUIRE(s.setUInt64(PERISTEP_VR_GAMUT_BONDS, 20000) == fmi3OK);
    s.log.clear();
    CHECK(s.initialize(0, 10) == fmi3Error);
    REQUIRE(s.log.errors() == 1);
    CHECK_THAT(s.log.records.back().message, Catch::Matchers::Contains("use fewer gamutBonds"));
  }
  SECTION("a load the bar cannot carry") {
    REQUIRE(s.initialize(0, 10) == fmi3OK);
    REQUIRE(s.setFloat64(PERISTEP_VR_LOAD_FACTOR, {5.0}) == fmi3OK);
    s.log.clear();
    CHECK(s.step(0, 1) == fmi3Error);
    requireOneError(s, "fmi3DoStep", "gamut bar: no equilibrium at an end force of");
  }
}
