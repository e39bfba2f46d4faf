// What the pictures say: units with the prefix that suits the values, the quantity a run ramps on the
// history's x axis, the phases of the material with their moduli and Void left out.
#include <catch2/catch.hpp>

#include "damage_picture.hpp"
#include "load_quantity.hpp"
#include "run_history.hpp"
#include "run_picture.hpp"
#include "unit_scale.hpp"

using namespace peristep::host;

namespace {

ResultLayout withParameters(std::vector<Attribute> parameters, const std::string& input) {
  ResultLayout l;
  l.parameterAttributes = std::move(parameters);
  l.inputName = input;
  return l;
}

std::vector<StepScalars> ramp(double to, int steps) {
  std::vector<StepScalars> out;
  for (int k = 1; k <= steps; ++k) out.push_back({0.25 * k, to * k / steps, {}});
  return out;
}

}  // namespace

TEST_CASE("units: the prefix puts the largest value between 0.1 and 100", "[host][plot]") {
  const auto check = [](const std::string& unit, double largest, double factor, const std::string& shown) {
    INFO(unit << " " << largest);
    const ScaledUnit s = scaledUnit(unit, largest);
    CHECK(s.factor == Approx(factor));
    CHECK(s.unit == shown);
  };
  check("m", 0.32e-6, 1e6, "µm");   // the glass-ceramic's opening: 0.32 µm
  check("m", 4e-9, 1e9, "nm");       // not 0.004 µm
  check("m", 8.3e-4, 1e3, "mm");
  check("m", 0.5, 1, "m");
  check("Pa.m^0.5", 1.2e6, 1e-6, "MPa.m^0.5");
  check("N/m", 6.2e4, 1e-3, "kN/m");
  check("J/m", 0.0098, 1e3, "mJ/m");
  check("s", 3.4e-5, 1e6, "µs");
  check("s", 5000, 1, "s");           // no kiloseconds
  check("kg/m3", 1190, 1, "kg/m3");   // already prefixed
  check("m2", 1e-6, 1, "m2");         // a prefix would be squared
  check("", 1e-7, 1, "");
  check("m", 0, 1, "m");
  CHECK(axisLabel("crackLength", "mm") == "crackLength [mm]");
  CHECK(axisLabel("brokenBonds", "") == "brokenBonds");
}

TEST_CASE("history: the x axis is the quantity the run ramps, in a unit that suits it", "[host][plot]") {
  // The glass-ceramic's opening, 8 nm per step up to 0.32 um.
  const ResultLayout glass = withParameters({{"scene", std::string("glassCeramic")}}, "loadDisplacement");
  const HistoryAxis opening = historyXAxis(glass, ramp(0.32e-6, 40), "m");
  CHECK(opening.label == "loadDisplacement [µm]");
  CHECK(opening.values.back() == Approx(0.32));

  // A specimen's loadFactor moves its held grips: the top grip's displacement is what is ramped.
  const ResultLayout specimen = withParameters(
      {{"scene", std::string("specimen")}, {"specimenModel", std::string("quasiStatic")},
       {"gripBottom", std::string("held")}, {"gripTop", std::string("held")}, {"gripBottomUy", std::vector<double>{-0.5e-5}},
       {"gripTopUy", std::vector<double>{1e-5}}, {"gripLeft", std::string("free")}, {"gripLeftUx", std::vector<double>{1.0}}},
      "loadFactor");
  const LoadQuantity grip = loadQuantity(specimen, "");
  CHECK(grip.name == "top grip displacement uy");
  CHECK(grip.unit == "m");
  CHECK(grip.perInput == 1e-5);
  const HistoryAxis pulled = historyXAxis(specimen, ramp(7.0, 9), "");
  CHECK(pulled.label == "top grip displacement uy [µm]");
  CHECK(pulled.values.back() == Approx(70));

  // The smooth scenes' loadFactor is the factor itself; the gamut bar's cyclic protocol ignores it.
  CHECK(historyXAxis(withParameters({{"scene", std::string("smooth")}}, "loadFactor"), ramp(1, 4), "").label ==
        "loadFactor");
  const ResultLayout bar = withParameters({{"scene", std::string("gamutBar")}, {"gamutProtocol", std::string("cyclic")}}, "loadFactor");
  const HistoryAxis steps = historyXAxis(bar, ramp(1, 53), "");
  CHECK(steps.label == "step");
  CHECK(steps.values.back() == 53);

  // An input held constant (the dynamic scenes): time, here in microseconds.
  std::vector<StepScalars> dynamic;
  for (int k = 1; k <= 17; ++k) dynamic.push_back({2e-6 * k, 1.0, {}});
  const HistoryAxis time = historyXAxis(withParameters({{"scene", std::string("plexiglassCrack")}}, "loadFactor"), dynamic, "");
  CHECK(time.label == "time [µs]");
  CHECK(time.values.back() == Approx(34));
}

TEST_CASE("picture: Void is empty and unnamed, phases are named with their moduli", "[host][png]") {
  // One row: a hole (E = 0), matrix 1 GPa, an inclusion 10 GPa; damage on the hole must not draw a crack.
  const std::vector<double> E{0.0, 1e9, 1e9, 1e10, 0.0};
  const RgbImage image = damagePicture(1, 5, {1.0, 0.0, 0.0, 0.0, 0.0}, E);
  CHECK(image.at(0, 0) == kVoid);
  CHECK(image.at(0, 1) == kSoftPhase);
  CHECK(image.at(0, 3) == kStiffPhase);
  CHECK(image.at(0, 4) == kVoid);

  ResultLayout plate;
  const auto legend = phaseLegend(plate, E);
  REQUIRE(legend.size() == 2);
  CHECK(legend[0].first == kSoftPhase);
  CHECK(legend[0].second == "E = 1 GPa");  // the matrix, not the hole's 0
  CHECK(legend[1].second == "E = 10 GPa");

  // One material with a hole: one entry, the material's modulus.
  const auto one = phaseLegend(plate, {0.0, 3e9, 3e9});
  REQUIRE(one.size() == 1);
  CHECK(one[0].second == "material, E = 3 GPa");

  // The glass-ceramic names its phases; a phase whose points differ gives its range.
  ResultLayout glass;
  glass.parameterAttributes = {{"scene", std::string("glassCeramic")}};
  const auto named = phaseLegend(glass, {80e9, 133e9, 80e9});
  CHECK(named[0].second == "glass, E = 80 GPa");
  CHECK(named[1].second == "crystal, E = 133 GPa");
  const auto field = phaseLegend(plate, {60e9, 65e9, 98e9, 100e9});
  CHECK(field[0].second == "E = 60–65 GPa");
  CHECK(field[1].second == "E = 98–100 GPa");
  CHECK(phaseLegend(plate, {}).front().second == "material");
}
