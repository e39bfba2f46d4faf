// Every picture the host writes, from every command that draws one, is a PNG that decodes (a picture
// gnuplot fails to draw is not left behind as an empty file); the bar's picture is its stress-strain
// path, a hole is drawn empty, and a sample study of a fracture scene draws the distribution of K_IC.
#include <catch2/catch.hpp>

#include <cmath>
#include <set>
#include <sstream>

#include "damage_picture.hpp"
#include "gnuplot.hpp"
#include "host_test_support.hpp"
#include "png_test_support.hpp"
#include "sample_plot.hpp"

using namespace host_test;
using namespace peristep::host;

namespace {

ProcessResult cli(const TempDir& dir, std::vector<std::string> args) {
  args.insert(args.begin(), PERISTEP_HOST_BINARY);
  const ProcessResult r = runProcess(args, dir.path());
  INFO(r.out << r.err);
  CHECK(r.exitCode == 0);
  return r;
}

// The notched plate of notched_plate.hpp (2 x 1 m, 41 x 21 points) with a round hole of Void, quasi-static.
std::string plateWithHole() {
  std::ostringstream e;
  e.precision(17);
  for (int j = 0; j < 21; ++j)
    for (int i = 0; i < 41; ++i) {
      const double x = -1.0 + 0.05 * i, y = -0.5 + 0.05 * j;
      e << (i + j ? ", " : "") << (std::hypot(x - 0.5, y + 0.25) <= 0.15 ? 0.0 : std::hypot(x, y - 0.1) <= 0.2 ? 1e10 : 1e9);
    }
  return "[parameters]\nscene = \"specimen\"\nnx = 41\nny = 21\nLx = 2.0\nLy = 1.0\nmaterialYoungsModulus = [" + e.str() +
         "]\ncrackX0 = [-1.0]\ncrackY0 = [-0.1]\ncrackX1 = [-0.6]\ncrackY1 = [0.1]\ngripBottom = \"held\"\n"
         "gripTop = \"held\"\ngripTopUy = 1e-5\n[loading]\ninput = \"loadFactor\"\nfrom = 4.75\nto = 7.0\nsteps = 9\n";
}

// The glass-ceramic of the picture test at h = 32 um, opened far enough for the crack to cross it.
const char* kSmallGlassCeramic = R"([parameters]
scene = "glassCeramic"
nx = 26
ny = 14
Lx = 800e-6
Ly = 416e-6
crystalFraction = 0.2
[loading]
input = "loadDisplacement"
from = 0.0
to = 0.4e-6
steps = 20
)";

}  // namespace

TEST_CASE("pictures: every PNG the host writes is non-empty and decodes", "[host][png][run][sample]") {
  REQUIRE(gnuplotAvailable());
  TempDir dir;
  writeText(dir / "hole.toml", plateWithHole());
  writeText(dir / "glass.toml", kSmallGlassCeramic);
  writeText(dir / "levels.toml", "[parameters]\nscene = \"smooth\"\n[convergence]\nlevels = [4, 8]\n");
  cli(dir, {"run"});  // the default scene
  cli(dir, {"run", PERISTEP_SOURCE_DIR "/scenes/smooth.toml"});
  cli(dir, {"run", PERISTEP_SOURCE_DIR "/scenes/gamut_bar.toml"});
  cli(dir, {"run", PERISTEP_HOST_TEST_DATA "/plexiglass_small.toml", "--out", "plexiglass.h5"});
  cli(dir, {"run", "hole.toml"});
  cli(dir, {"convergence", "levels.toml"});
  cli(dir, {"sample", PERISTEP_SOURCE_DIR "/scenes/smooth_sampling.toml", "--rule", "tensor", "--level", "1,2,3", "--set",
            "nx=9", "--set", "ny=9", "--out", "collocation.h5"});
  const ProcessResult mc = cli(dir, {"sample", "glass.toml", "--rule", "mc", "--samples", "6"});
  CHECK_THAT(mc.out, Catch::Matchers::Contains("wrote glass_mc.png"));

  std::set<std::string> pictures;
  for (const auto& entry : fs::recursive_directory_iterator(dir.path())) {
    if (entry.path().extension() != ".png") continue;
    const std::string name = entry.path().filename().string();
    INFO(name);
    pictures.insert(name);
    CHECK(entry.file_size() > 0);
    Picture p;
    CHECK_NOTHROW(p = readPng(entry.path()));
    CHECK(p.width >= 400);
    CHECK(p.height >= 300);
    CHECK(countInk(p, 0, 0, p.width, p.height) > 1000);  // something is drawn
  }
  for (const char* expected : {"peristep_default.png", "peristep_default_history.png", "smooth.png", "smooth_history.png",
                               "gamut_bar.png", "gamut_bar_history.png", "plexiglass.png", "plexiglass_history.png",
                               "hole.png", "hole_history.png", "levels.png", "collocation.png", "glass_mc.png"})
    CHECK(pictures.count(expected) == 1);

  // The bar has nothing on the plate grid: its picture is the stress-strain path, a curve in colour.
  const Picture bar = readPng(dir / "gamut_bar.png");
  CHECK(countColoured(bar, 0, 0, bar.width, bar.height) > 2000);
  // The hole (0.3 m across a 2 m plate, about 110 px) is left empty inside the plot, not drawn as matrix.
  const Picture hole = readPng(dir / "hole.png");
  CHECK(countColour(hole, kVoid) > 0);
  std::size_t empty = 0;
  for (std::uint32_t y = 90; y + 90 < hole.height; ++y)
    for (std::uint32_t x = 120; x < 820; ++x) empty += hole.at(x, y) == kVoid;
  CHECK(empty > 5000);
  CHECK(countColour(hole, kSoftPhase) > 50000);
  // The Monte Carlo study of the fracture scene: one panel, the distribution of K_IC.
  const Picture study = readPng(dir / "glass_mc.png");
  CHECK(study.width == samplePlotWidth(1));
  CHECK(study.height == samplePlotHeight(1));
  CHECK(countColoured(study, 0, 0, study.width, study.height) > 5000);  // the histogram's bars and the lines
}

TEST_CASE("sample plot: a result's distribution beside the errors, two panels to a row", "[host][plot]") {
  REQUIRE(gnuplotAvailable());
  TempDir dir;
  writeText(dir / "study.csv",
            "level,samples,computed,errorMean,errorStd,diffMean,diffStd,seconds\n1,3,3,1e-3,2e-3,5e-4,6e-4,0.1\n"
            "2,5,2,4e-4,9e-4,1e-4,2e-4,0.2\n3,9,4,1e-4,3e-4,,,0.4\n");
  ResultDistribution kic{"toughnessKIC", "Pa.m^0.5", {0.95e6, 1.0e6, 1.02e6, 1.1e6, 1.2e6}, 1.054e6, 0.1e6, 0.97e6, 1.14e6,
                         "95% interval of the mean"};
  CHECK(plotSampleStudy(dir / "study.csv", "two", {kic}) == "wrote " + (dir / "study.png").string());
  const Picture p = readPng(dir / "study.png");
  CHECK(p.width == samplePlotWidth(2));
  CHECK(p.height == samplePlotHeight(2));
  CHECK(samplePlotWidth(2) > samplePlotWidth(1));

  // A single level without exact errors: the distribution alone.
  writeText(dir / "one.csv", "level,samples,computed,errorMean,errorStd,diffMean,diffStd,seconds\n1,5,5,,,,,0.1\n");
  CHECK(plotSampleStudy(dir / "one.csv", "one", {kic}) == "wrote " + (dir / "one.png").string());
  CHECK(readPng(dir / "one.png").width == samplePlotWidth(1));
  // Every sample alike: one bar, still a picture.
  kic.values.assign(4, 1e6);
  CHECK(plotSampleStudy(dir / "one.csv", "alike", {kic}) == "wrote " + (dir / "one.png").string());
  CHECK(fs::file_size(dir / "one.png") > 0);
}

TEST_CASE("gnuplot: a picture gnuplot fails to draw leaves no empty file behind", "[host][plot]") {
  REQUIRE(gnuplotAvailable());
  TempDir dir;
  const fs::path png = dir / "broken.png";
  const std::string problem = runGnuplot("set terminal pngcairo\nset output " + gnuplotQuoted(png.string()) +
                                             "\nplot no_such_function(x)\n",
                                         png);
  CHECK_FALSE(problem.empty());
  CHECK_FALSE(fs::exists(png));
}
