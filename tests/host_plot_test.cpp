// Plots drawn by gnuplot: the history of a run's scalar outputs (panels grouped by unit, x axis the
// load or the time), the refinement study and the sample study; each file a valid PNG of its size.
#include <catch2/catch.hpp>

#include <cmath>

#include "gnuplot.hpp"
#include "gnuplot_plot.hpp"
#include "host_test_support.hpp"
#include "png_test_support.hpp"
#include "run_history.hpp"
#include "sample_plot.hpp"

using namespace host_test;
using namespace peristep::host;

namespace {

// Four steps of a dynamic run: two energies (J/m) and a counter change, errorL2 stays 0.
ResultLayout dynamicLayout() {
  ResultLayout l;
  l.scalars = {{"strainEnergy", {}, "J/m", ""}, {"errorL2", {}, "m", ""}, {"kineticEnergy", {}, "J/m", ""},
               {"forceEvaluations", {}, "", ""}, {"brokenBonds", {}, "", ""}};
  l.inputName = "loadFactor";
  return l;
}

std::vector<StepScalars> dynamicSteps() {
  std::vector<StepScalars> steps;
  for (int k = 1; k <= 4; ++k) steps.push_back({2e-6 * k, 1.0, {0.4 * k, 0.0, 1.3 + 0.1 * k, 500.0 * k, k > 2 ? 8.0 : 0.0}});
  return steps;
}

}  // namespace

TEST_CASE("history: outputs that change, grouped by unit, unitless ones alone", "[host][plot]") {
  const auto panels = historyPanels(dynamicLayout(), dynamicSteps());
  REQUIRE(panels.size() == 3);
  CHECK(panels[0] == std::vector<std::size_t>{0, 2});  // the two energies
  CHECK(panels[1] == std::vector<std::size_t>{3});
  CHECK(panels[2] == std::vector<std::size_t>{4});
  CHECK(historyPlotHeight(3) == 2 * kHistoryPanelHeight + 40);
  CHECK(historyPlotHeight(1) == kHistoryPanelHeight + 40);
}

TEST_CASE("history: the CSV holds every step exactly and the plot is a PNG of its size", "[host][plot]") {
  TempDir dir;
  const ResultLayout layout = dynamicLayout();
  writeHistoryCsv(dir / "run.csv", layout, dynamicSteps());
  const std::string csv = readText(dir / "run.csv");
  CHECK_THAT(csv, Catch::Matchers::StartsWith(
                      "step,time,loadFactor,strainEnergy,errorL2,kineticEnergy,forceEvaluations,brokenBonds\n"
                      "1,1.9999999999999999e-06,1,0.40000000000000002,0,1.4000000000000001,500,0\n"));
  CHECK(lineCount(csv) == 5);

  REQUIRE(gnuplotAvailable());
  CHECK(plotHistory(dir / "run.png", layout, dynamicSteps(), "dynamic", "") == "");
  const Picture p = readPng(dir / "run.png");
  CHECK(p.width == kHistoryPlotWidth);
  CHECK(p.height == historyPlotHeight(3));
  CHECK(countColoured(p, 0, 0, p.width, p.height) > 500);  // curves

  // Nothing changes: nothing to draw, and no file.
  std::vector<StepScalars> still(3, StepScalars{1.0, 1.0, {1, 0, 2, 3, 4}});
  CHECK(plotHistory(dir / "still.png", layout, still, "still", "") == "no output changes during the run");
  CHECK_FALSE(fs::exists(dir / "still.png"));
}

TEST_CASE("convergence plot: error against h and against wall time, with both fits", "[host][plot]") {
  REQUIRE(gnuplotAvailable());
  TempDir dir;
  std::vector<LevelResult> rows;
  for (int k = 0; k < 4; ++k) {
    LevelResult r;
    r.level = 8u << k;
    r.h = 1.0 / static_cast<double>(r.level);
    r.errorL2 = 0.3 * r.h * r.h;
    r.wallSeconds = 0.01 * std::pow(4.0, k);
    rows.push_back(r);
  }
  CHECK(plotConvergence(rows, dir / "study.png", "study") == "");
  const Picture p = readPng(dir / "study.png");
  CHECK(p.width == kConvergencePlotWidth);
  CHECK(p.height == kConvergencePlotHeight);
}

TEST_CASE("sample plot: errors of mean and std against samples, from the study's CSV", "[host][plot]") {
  TempDir dir;
  writeText(dir / "study.csv",
            "level,samples,computed,errorMean,errorStd,diffMean,diffStd,seconds,mean_errorL2,std_errorL2\n"
            "1,3,3,1e-3,2e-3,5e-4,6e-4,0.1,1,0\n"
            "2,5,2,4e-4,9e-4,1e-4,2e-4,0.2,1,0\n"
            "3,9,4,1e-4,3e-4,,,0.4,1,0\n");
  if (gnuplotAvailable()) {
    CHECK(plotSampleStudy(dir / "study.csv", "smooth, rule smolyak") == "wrote " + (dir / "study.png").string());
    const Picture p = readPng(dir / "study.png");
    CHECK(p.width == kSamplePlotWidth);
    CHECK(p.height == kSamplePlotHeight);
    CHECK(countColoured(p, 0, 0, p.width, p.height) > 500);
  } else {
    CHECK(plotSampleStudy(dir / "study.csv", "x") == "no plot: gnuplot not on PATH");
  }
  // One level of a scene without exact moments: nothing to draw.
  writeText(dir / "one.csv", "level,samples,computed,errorMean,errorStd,diffMean,diffStd,seconds\n1,3,3,,,,,0.1\n");
  CHECK_THAT(plotSampleStudy(dir / "one.csv", "x"), Catch::Matchers::Contains("has no errors to draw"));
  CHECK_FALSE(fs::exists(dir / "one.png"));
}
