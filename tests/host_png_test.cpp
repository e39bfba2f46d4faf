// Pictures: the damage colours and the plain PNG writer (bench/glass_ceramic) read back with libpng;
// the annotated picture `peristep run` draws with gnuplot (title, colour bar, axes, legend), for hand-
// made layouts, a small glass-ceramic run, the default run (a glass-ceramic crack) and Test 1.
#include <catch2/catch.hpp>

#include <cmath>

#include "damage_picture.hpp"
#include "gnuplot.hpp"
#include "host_errors.hpp"
#include "host_test_support.hpp"
#include "png_test_support.hpp"
#include "png_writer.hpp"
#include "run_picture.hpp"

using namespace host_test;
using namespace peristep::host;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

// The colour at the centre of grid point (row, col)'s block, row 0 being the bottom of the picture.
Rgb pointColour(const Picture& p, std::uint64_t ny, std::uint64_t row, std::uint64_t col, std::uint64_t k) {
  return p.at(static_cast<std::uint32_t>(col * k + k / 2), static_cast<std::uint32_t>((ny - 1 - row) * k + k / 2));
}

}  // namespace

namespace peristep::host {
std::ostream& operator<<(std::ostream& os, const Rgb& c) {
  return os << '(' << int(c.r) << ", " << int(c.g) << ", " << int(c.b) << ')';
}
}  // namespace peristep::host

TEST_CASE("png: each grid point becomes a block wide enough for an 800 px picture", "[host][png]") {
  CHECK(pictureBlockSize(26) == 31);  // 806 px
  CHECK(pictureBlockSize(51) == 16);  // 816 px
  CHECK(pictureBlockSize(400) == 2);
  CHECK(pictureBlockSize(401) == 2);
  CHECK(pictureBlockSize(800) == 1);
  CHECK(pictureBlockSize(1601) == 1);
}

TEST_CASE("png: phases by Young's modulus, cracks over them", "[host][png]") {
  // One row: glass, crystal, glass just below the crack threshold, crystal at it, fully broken glass.
  const std::vector<double> E{80e9, 133e9, 80e9, 133e9, 80e9};
  const std::vector<double> d{0.0, 0.2, kCrackDamage - 0.01, kCrackDamage, 1.0};
  const RgbImage image = damagePicture(1, 5, d, E);
  CHECK(image.at(0, 0) == kSoftPhase);
  CHECK(image.at(0, 1) == kStiffPhase);
  CHECK(image.at(0, 2) == kSoftPhase);
  CHECK(image.at(0, 3) == kCrackOnset);
  CHECK(image.at(0, 4) == kCrackFull);

  // More damage is brighter; a uniform material, or none known, is the middle blue.
  const RgbImage ramp = damagePicture(1, 3, {0.5, 0.75, 0.95}, {});
  const auto brightness = [](const Rgb& c) { return int(c.r) + c.g + c.b; };
  CHECK(brightness(ramp.at(0, 0)) < brightness(ramp.at(0, 1)));
  CHECK(brightness(ramp.at(0, 1)) < brightness(ramp.at(0, 2)));
  CHECK(damagePicture(1, 2, {0, 0}, {133e9, 133e9}).pixels == std::vector<Rgb>(2, kUniformPhase));
  CHECK(damagePicture(1, 2, {0, 0}, {}).pixels == std::vector<Rgb>(2, kUniformPhase));
  // The midpoint of the range splits the phases, whatever the two values are.
  const RgbImage split = damagePicture(1, 3, {0, 0, 0}, {1.0, 2.0, 1.6});
  CHECK(split.at(0, 2) == kStiffPhase);

  CHECK_THROWS_AS(damagePicture(2, 2, {0, 0, 0}, {}), RunError);
  CHECK_THROWS_AS(damagePicture(1, 2, {0, 0}, {1.0}), RunError);
}

TEST_CASE("png: a written picture reads back with row 0 at the bottom", "[host][png]") {
  TempDir dir;
  // ny = 3, nx = 4: a crack along the bottom row's left half, a crystal in the top right corner.
  std::vector<double> E(12, 80e9), d(12, 0.0);
  E[2 * 4 + 3] = 133e9;
  d[0 * 4 + 0] = 1.0;
  d[0 * 4 + 1] = 0.5;
  const fs::path file = dir / "picture.png";
  writePng(file, damagePicture(3, 4, d, E));

  const Picture p = readPng(file);
  const std::uint64_t k = pictureBlockSize(4);
  REQUIRE(k == 200);
  CHECK(p.width == 800);
  CHECK(p.height == 600);
  CHECK(p.colour);
  CHECK_FALSE(p.alpha);

  CHECK(pointColour(p, 3, 0, 0, k) == kCrackFull);         // damaged point
  CHECK(p.at(0, p.height - 1) == kCrackFull);               // ... whose block holds the bottom-left corner
  CHECK(p.at(k - 1, p.height - k) == kCrackFull);           // ... and is k x k
  CHECK(p.at(k, p.height - 1) != kCrackFull);
  CHECK(p.at(0, p.height - 1 - k) == kSoftPhase);
  CHECK(pointColour(p, 3, 2, 3, k) == kStiffPhase);         // intact crystal point
  CHECK(p.at(p.width - 1, 0) == kStiffPhase);               // ... in the top-right corner
  CHECK(pointColour(p, 3, 2, 0, k) == kSoftPhase);          // top left: intact glass, not the crack
  const Rgb half = pointColour(p, 3, 0, 1, k);
  CHECK(half.r > half.b);                                   // damage 0.5 is drawn as crack, not as material
}

TEST_CASE("png: an unwritable picture is a RunError", "[host][png]") {
  TempDir dir;
  const RgbImage image = damagePicture(1, 1, {0.0}, {});
  CHECK_THROWS_AS(writePng(dir / "no_such_dir" / "p.png", image), RunError);
  CHECK_THROWS_AS(writePng(dir / "empty.png", RgbImage{}), RunError);
}

namespace {

// A plate of ny x nx points, h = 0.1 mm, left half soft (80 GPa), right half stiff (133 GPa), damage
// `crack` on the bottom row's left half; ux = 1 um * x / Lx.
ResultLayout plateLayout(std::uint64_t ny, std::uint64_t nx) {
  ResultLayout l;
  l.ny = ny;
  l.nx = nx;
  std::vector<double> x, y;
  for (std::uint64_t j = 0; j < ny; ++j)
    for (std::uint64_t i = 0; i < nx; ++i) x.push_back(1e-4 * static_cast<double>(i)), y.push_back(1e-4 * static_cast<double>(j));
  l.constantArrays = {{"x", {ny, nx}, "m", ""}, {"y", {ny, nx}, "m", ""}};
  l.constantValues = {x, y};
  l.fields = {{"ux", {ny, nx}, "m", ""}, {"uy", {ny, nx}, "m", ""}, {"damage", {ny, nx}, "", ""},
              {"youngsModulus", {ny, nx}, "Pa", ""}};
  l.inputName = "loadDisplacement";
  l.parameterAttributes = {{"scene", std::string("glassCeramic")}};
  return l;
}

StepValues plateStep(const ResultLayout& l, double crack) {
  StepValues s;
  s.time = 1;
  s.input = 5e-8;
  s.fields.assign(4, std::vector<double>(l.ny * l.nx, 0.0));
  for (std::uint64_t j = 0; j < l.ny; ++j)
    for (std::uint64_t i = 0; i < l.nx; ++i) {
      const std::size_t k = j * l.nx + i;
      s.fields[0][k] = 1e-6 * static_cast<double>(i) / static_cast<double>(l.nx);
      s.fields[2][k] = j == 0 && i < l.nx / 2 ? crack : 0.0;
      s.fields[3][k] = i < l.nx / 2 ? 80e9 : 133e9;
    }
  return s;
}

}  // namespace

TEST_CASE("picture: the size follows the domain's aspect ratio within bounds", "[host][png]") {
  ResultLayout l;
  l.ny = l.nx = 33;
  CHECK(runPictureSize(l).width == 1000);
  CHECK(runPictureSize(l).height == 890);
  l.ny = 14, l.nx = 26;
  CHECK(runPictureSize(l).height == 567);
  l.ny = 1, l.nx = 1000;
  CHECK(runPictureSize(l).height == 400);
  l.ny = 1000, l.nx = 10;
  CHECK(runPictureSize(l).height == 1300);
}

TEST_CASE("picture: phases with a legend, cracks on a colour bar, title and axes", "[host][png]") {
  REQUIRE(gnuplotAvailable());
  TempDir dir;
  const ResultLayout layout = plateLayout(10, 20);
  const StepValues step = plateStep(layout, 1.0);
  CHECK(writeRunPicture(dir / "plate.png", layout, step, {"plate", 3, 7, "m"}) == "");
  const Picture p = readPng(dir / "plate.png");
  CHECK(p.width == runPictureSize(layout).width);
  CHECK(p.height == runPictureSize(layout).height);
  // Both phases and the fully broken points in their colours: large areas of each.
  CHECK(countColour(p, kSoftPhase) > 20000);
  CHECK(countColour(p, kStiffPhase) > 20000);
  // Title above the plot, legend below it, colour bar (red to yellow) at the right.
  CHECK(countInk(p, 0, 0, p.width, 40) > 100);
  CHECK(countInk(p, 0, p.height - 25, p.width, p.height) > 100);
  CHECK(countColoured(p, p.width - 120, 0, p.width, p.height) > 2000);

  // Damage below the crack threshold is drawn as material, still with its colour bar.
  CHECK(writeRunPicture(dir / "intact.png", layout, plateStep(layout, 0.2), {"plate", 1, 1, "m"}) == "");
  const Picture intact = readPng(dir / "intact.png");
  // The fully broken points: a large area of the crack colour (which the legend and colour bar also show).
  CHECK(countColour(p, kCrackFull) > countColour(intact, kCrackFull) + 1000);
  CHECK(countColoured(intact, intact.width - 120, 0, intact.width, intact.height) > 2000);
}

TEST_CASE("picture: without damage, the displacement magnitude on the deformed grid", "[host][png]") {
  REQUIRE(gnuplotAvailable());
  TempDir dir;
  ResultLayout layout = plateLayout(12, 12);
  const StepValues step = plateStep(layout, 0.0);
  CHECK(writeRunPicture(dir / "u.png", layout, step, {"smooth", 4, 4, ""}) == "");
  const Picture p = readPng(dir / "u.png");
  CHECK(p.width == 1000);
  CHECK(p.height == 890);
  CHECK(countColour(p, kSoftPhase) == 0);  // no material map
  // The viridis ends: |u| = 0 at the left edge, the largest at the right.
  const auto near = [&](Rgb c) {
    std::size_t n = 0;
    for (std::uint32_t y = 0; y < p.height; ++y)
      for (std::uint32_t x = 0; x < p.width; ++x) {
        const Rgb q = p.at(x, y);
        n += std::abs(q.r - c.r) + std::abs(q.g - c.g) + std::abs(q.b - c.b) < 30;
      }
    return n;
  };
  CHECK(near({0x44, 0x01, 0x54}) > 5000);
  CHECK(near({0xfd, 0xe7, 0x25}) > 5000);

  layout.constantArrays.clear();
  layout.constantValues.clear();
  CHECK(writeRunPicture(dir / "none.png", layout, step, {"smooth", 1, 1, ""}) == "no point coordinates x, y on the grid");
  CHECK_FALSE(fs::exists(dir / "none.png"));
}

TEST_CASE("peristep run: a glass-ceramic run leaves a picture, its history and the plot of it", "[host][png][run]") {
  REQUIRE(gnuplotAvailable());
  TempDir dir;
  const ProcessResult r =
      runProcess({PERISTEP_HOST_BINARY, "run", PERISTEP_HOST_TEST_DATA "/glass_ceramic_small.toml", "--out", "small.h5"},
                 dir.path());
  INFO("stdout:\n" << r.out << "\nstderr:\n" << r.err);
  REQUIRE(r.exitCode == 0);
  CHECK_THAT(r.out,
             Contains("wrote small.h5 (3 steps, 14 x 26 points), small.xmf, small.csv, small.png and small_history.png"));

  const Picture p = readPng(dir / "small.png");
  CHECK(p.width == 1000);
  CHECK(p.height == 567);
  CHECK(p.colour);
  CHECK(countColour(p, kSoftPhase) > 10000);   // glass
  CHECK(countColour(p, kStiffPhase) > 2000);   // crystal
  // The 100 um pre-crack enters from the left edge at mid-height: drawn in the crack colours.
  std::size_t crack = 0;
  for (std::uint32_t y = p.height / 3; y < 2 * p.height / 3; ++y)
    for (std::uint32_t x = 0; x < p.width / 4; ++x) {
      const Rgb c = p.at(x, y);
      crack += c.r > 150 && c.b < 80;
    }
  CHECK(crack > 500);

  // The history: one row per step, the load-displacement curve drawn.
  const std::string csv = readText(dir / "small.csv");
  CHECK(lineCount(csv) == 4);
  CHECK_THAT(csv, StartsWith("step,time,loadDisplacement,"));
  const Picture history = readPng(dir / "small_history.png");
  CHECK(history.width == 1100);
  CHECK(history.height == 380);
}

TEST_CASE("peristep run: Test 1 draws the displacement, not a material map", "[host][png][run]") {
  REQUIRE(gnuplotAvailable());
  TempDir dir;
  const ProcessResult r =
      runProcess({PERISTEP_HOST_BINARY, "run", PERISTEP_SOURCE_DIR "/scenes/smooth.toml", "--out", "d.h5"}, dir.path());
  INFO("stdout:\n" << r.out << "\nstderr:\n" << r.err);
  REQUIRE(r.exitCode == 0);
  const Picture p = readPng(dir / "d.png");
  CHECK(p.width == 1000);
  CHECK(p.height == 890);
  CHECK(countColour(p, kUniformPhase) == 0);
  CHECK(countColour(p, kSoftPhase) == 0);
  CHECK(countColoured(p, 100, 70, 830, 800) > 400000);  // the plot area is a colour map
}

TEST_CASE("peristep run: the default run's picture shows both phases, the crack and a colour bar", "[host][png][run]") {
  REQUIRE(gnuplotAvailable());
  TempDir dir;
  const ProcessResult r = runProcess({PERISTEP_HOST_BINARY, "run"}, dir.path());
  INFO("stdout:\n" << r.out << "\nstderr:\n" << r.err);
  REQUIRE(r.exitCode == 0);
  const Picture p = readPng(dir / "peristep_default.png");
  CHECK(p.width == 1000);
  CHECK(countColour(p, kSoftPhase) > 50000);  // glass
  CHECK(countColour(p, kStiffPhase) > 10000);  // crystal
  // The crack (red to yellow) in the plot area's right half: it crossed the plate.
  std::size_t crack = 0;
  for (std::uint32_t y = 80; y + 80 < p.height; ++y)
    for (std::uint32_t x = p.width / 2; x < p.width - 160; ++x) {
      const Rgb c = p.at(x, y);
      crack += c.r > 150 && c.b < 80;
    }
  CHECK(crack > 500);
  CHECK(countColoured(p, p.width - 120, 0, p.width, p.height) > 2000);  // the colour bar
}
