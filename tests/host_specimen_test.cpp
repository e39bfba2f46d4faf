// `peristep run` on a scene file that describes its own specimen (scene = "specimen"): the notched plate
// with the stiff inclusion of notched_plate.hpp, its material maps written into the file as arrays,
// cracks from the notch past the inclusion.
#include <catch2/catch.hpp>

#include <algorithm>
#include <sstream>

#include "host_test_support.hpp"
#include "notched_plate.hpp"

using namespace host_test;
using namespace notched_plate;

namespace {

std::string tomlArray(const std::vector<double>& v) {
  std::ostringstream s;
  s.precision(17);
  s << '[';
  for (std::size_t i = 0; i < v.size(); ++i) s << (i ? ", " : "") << v[i];
  s << ']';
  return s.str();
}

// `peristep run` of a scene file in dir, its CSV's lines (the run's outputs go to dir/<name>.h5, .csv).
std::vector<std::string> csvRows(const TempDir& dir, const std::string& sceneFile, const std::string& name) {
  const ProcessResult r =
      runProcess({PERISTEP_HOST_BINARY, "run", sceneFile, "--fmu", PERISTEP_FMU, "--out", name + ".h5"}, dir.path());
  INFO(r.err);
  REQUIRE(r.exitCode == 0);
  std::vector<std::string> rows;
  std::istringstream csv(readText(dir / (name + ".csv")));
  for (std::string line; std::getline(csv, line);) rows.push_back(line);
  return rows;
}

}  // namespace

TEST_CASE("peristep run: a specimen described in the scene file cracks from its notch past the inclusion",
          "[host][run][specimen]") {
  TempDir dir;
  std::ostringstream toml;
  toml.precision(17);
  // Loads 5.0 ... 7.0: the crack starts from the notch and runs past the inclusion (the C ABI test pulls
  // the same plate up from below the first break).
  toml << "[parameters]\nscene = \"specimen\"\nnx = " << kNx << "\nny = " << kNy << "\nLx = " << kLx
       << "\nLy = " << kLy << "\nmaterialYoungsModulus = " << tomlArray(youngsModulus(true))
       << "\nmaterialFractureEnergy = " << tomlArray(fractureEnergy(true)) << "\ncrackX0 = [" << kNotch[0]
       << "]\ncrackY0 = [" << kNotch[1] << "]\ncrackX1 = [" << kNotch[2] << "]\ncrackY1 = [" << kNotch[3]
       << "]\ngripBottom = \"held\"\ngripTop = \"held\"\ngripTopUy = " << kTopPull
       << "\n[loading]\ninput = \"loadFactor\"\nfrom = 4.75\nto = 7.0\nsteps = 9\n";
  writeText(dir / "notched.toml", toml.str());
  const ProcessResult r =
      runProcess({PERISTEP_HOST_BINARY, "run", "notched.toml", "--fmu", PERISTEP_FMU, "--out", "n.h5"}, dir.path());
  INFO(r.err);
  REQUIRE(r.exitCode == 0);
  const hid_t f = openHdf5(dir / "n.h5");
  REQUIRE(f >= 0);
  const Dataset damage = readDataset(f, "/fields/damage");
  H5Fclose(f);
  REQUIRE(damage.shape == std::vector<hsize_t>{9, kNy, kNx});
  const std::vector<double> last(damage.values.end() - kPoints, damage.values.end());
  CHECK(crackFront(last) >= kPassed);
  CHECK(crackedInInclusion(last) == 0);
}

// The plate of the C ABI test (tests/fmi_dynamic_specimen_test.cpp) without the hole: Young's modulus
// 3 K (1 - 2 nu) of 001 Table 1 everywhere, the top grip at 0.2 m/s, `steps` steps of 50 us; `extra`
// lines join [parameters].
std::string dynamicPlate(int steps, const std::string& extra = "") {
  std::ostringstream toml;
  toml.precision(17);
  toml << "[parameters]\nscene = \"specimen\"\nspecimenModel = \"dynamic\"\nnx = " << kNx << "\nny = " << kNy
       << "\nLx = " << kLx << "\nLy = " << kLy
       << "\nmaterialYoungsModulus = " << tomlArray(std::vector<double>(kPoints, 3 * 25e9 * (1 - 2 * 0.25)))
       << "\ncrackX0 = [" << kNotch[0] << "]\ncrackY0 = [" << kNotch[1] << "]\ncrackX1 = [" << kNotch[2]
       << "]\ncrackY1 = [" << kNotch[3] << "]\ngripBottom = \"held\"\ngripTop = \"held\"\ngripTopVy = 0.2\n"
       << extra << "[loading]\ninput = \"loadFactor\"\nfrom = 1.0\nto = 1.0\nsteps = " << steps
       << "\nstartTime = 0.0\nstopTime = " << 5e-5 * steps << "\n";
  return toml.str();
}

TEST_CASE("peristep run: a dynamic specimen from a scene file cracks from its notch as the grip pulls",
          "[host][run][specimen][dynamic]") {
  TempDir dir;
  writeText(dir / "dynamic.toml", dynamicPlate(30));
  const ProcessResult r =
      runProcess({PERISTEP_HOST_BINARY, "run", "dynamic.toml", "--fmu", PERISTEP_FMU, "--out", "d.h5"}, dir.path());
  INFO(r.err);
  REQUIRE(r.exitCode == 0);
  const hid_t f = openHdf5(dir / "d.h5");
  REQUIRE(f >= 0);
  const Dataset damage = readDataset(f, "/fields/damage"), crack = readDataset(f, "/scalars/crackLength");
  const Dataset work = readDataset(f, "/scalars/externalWork"), time = readDataset(f, "/time");
  H5Fclose(f);
  REQUIRE(damage.shape == std::vector<hsize_t>{30, kNy, kNx});
  CHECK(time.values.back() == Approx(1.5e-3));
  CHECK(std::is_sorted(work.values.begin(), work.values.end()));  // the grip only pulls
  CHECK(crack.values.front() == 0.0);
  CHECK(crack.values.back() > 0.5);
  // Z > 1 (001:(104)) along the crack has run from the notch tip at x = -0.6 past the plate's middle.
  const std::vector<double> last(damage.values.end() - kPoints, damage.values.end());
  double far = -1;
  for (std::size_t i = 0; i < kPoints; ++i)
    if (last[i] > 1) far = std::max(far, xOf(i));
  CHECK(far > 0.0);
}

TEST_CASE("peristep sample: a dynamic specimen with a KL modulus field, collocated in two coordinates",
          "[host][sample][specimen][dynamic]") {
  // Smolyak level 1 in xi1, xi2 (5 nodes, the first at xi = 0); `peristep run` of the same file at xi = 0
  // gives the first sample's crack length bit for bit.
  TempDir dir;
  writeText(dir / "kl.toml", dynamicPlate(20, "materialField = \"klField\"\nxi = [0.0, 0.0]\n"));
  const ProcessResult s = runProcess({PERISTEP_HOST_BINARY, "sample", "kl.toml", "--rule", "smolyak", "--level", "1",
                                      "--out", "s.h5", "--fmu", PERISTEP_FMU},
                                     dir.path());
  INFO(s.out << s.err);
  REQUIRE(s.exitCode == 0);
  const ProcessResult r =
      runProcess({PERISTEP_HOST_BINARY, "run", "kl.toml", "--fmu", PERISTEP_FMU, "--out", "r.h5"}, dir.path());
  REQUIRE(r.exitCode == 0);
  hid_t f = openHdf5(dir / "s.h5");
  REQUIRE(f >= 0);
  const Dataset nodes = readDataset(f, "/level_1/nodes"), crack = readDataset(f, "/level_1/samples/crackLength");
  const Dataset E = readDataset(f, "/level_1/samples/youngsModulus");
  H5Fclose(f);
  f = openHdf5(dir / "r.h5");
  REQUIRE(f >= 0);
  const Dataset runCrack = readDataset(f, "/scalars/crackLength");
  H5Fclose(f);
  REQUIRE(nodes.shape == std::vector<hsize_t>{5, 2});
  REQUIRE(crack.values.size() == 5);
  CHECK(nodes.values[0] == 0.0);
  CHECK(nodes.values[1] == 0.0);
  CHECK(crack.values[0] == runCrack.values.back());
  // The field changes the plate (its modulus) and with it the crack.
  CHECK(E.values[kPoints] != E.values[0]);
  CHECK(*std::max_element(crack.values.begin(), crack.values.end()) >
        *std::min_element(crack.values.begin(), crack.values.end()));
}

// The glassCeramic scene is a preset of the specimen: scenes/glass_ceramic_specimen.toml spells it out in
// specimen variables and gives the CSV of scenes/glass_ceramic.toml value for value (only the ramped
// input's name differs: loadFactor there, loadDisplacement here).
TEST_CASE("peristep run: scenes/glass_ceramic_specimen.toml reproduces scenes/glass_ceramic.toml",
          "[host][run][specimen]") {
  TempDir dir;
  std::vector<std::string> rows[2];
  const char* files[2] = {"glass_ceramic.toml", "glass_ceramic_specimen.toml"};
  for (int k = 0; k < 2; ++k) {
    const std::string out = "run" + std::to_string(k) + ".h5";
    const ProcessResult r = runProcess({PERISTEP_HOST_BINARY, "run", std::string(PERISTEP_SOURCE_DIR "/scenes/") + files[k],
                                        "--fmu", PERISTEP_FMU, "--out", out},
                                       dir.path());
    INFO(r.err);
    REQUIRE(r.exitCode == 0);
    std::istringstream csv(readText(dir / ("run" + std::to_string(k) + ".csv")));
    for (std::string line; std::getline(csv, line);) rows[k].push_back(line);
  }
  REQUIRE(rows[0].size() > 50);  // the crack crossed the plate after most of the 75 steps
  REQUIRE(rows[0].size() == rows[1].size());
  CHECK(rows[0][0].find(",loadDisplacement,") != std::string::npos);
  CHECK(rows[1][0].find(",loadFactor,") != std::string::npos);
  for (std::size_t i = 1; i < rows[0].size(); ++i) {
    INFO("row " << i);
    CHECK(rows[0][i] == rows[1][i]);
  }
}

TEST_CASE("peristep run: scenes/kl_plate.toml equals the elastic specimen spelled out in a scene file",
          "[host][run][specimen]") {
  TempDir dir;
  // The preset of component/scenes/kl_plate.cpp written as specimen variables, on the scene file's grid.
  const std::size_t n = 33 * 33;
  std::string specimen = readText(PERISTEP_SOURCE_DIR "/scenes/kl_plate.toml");
  const std::string scene = "scene = \"klPlate\"";
  REQUIRE(specimen.find(scene) != std::string::npos);
  specimen.replace(specimen.find(scene), scene.size(),
                   "scene = \"specimen\"\nspecimenModel = \"elastic\"\nmaterialField = \"klField\"\n"
                   "materialYoungsModulus = " + tomlArray(std::vector<double>(n, 1.0)) +
                       "\nmaterialPoissonRatio = " + tomlArray(std::vector<double>(n, 0.3)) +
                       "\ngripLeft = \"held\"\ngripRight = \"held\"\ngripBottom = \"held\"\ngripTop = \"held\"\n"
                       "gripBottomUy = 0.0\ngripTopUy = 0.0\ncollarDuyDy = 0.01");
  writeText(dir / "kl_specimen.toml", specimen);
  const std::vector<std::string> preset = csvRows(dir, PERISTEP_SOURCE_DIR "/scenes/kl_plate.toml", "preset");
  REQUIRE(preset.size() == 3);  // header and two load steps
  REQUIRE(preset == csvRows(dir, (dir / "kl_specimen.toml").string(), "specimen"));
}

TEST_CASE("peristep run: the Plexiglass crack equals the dynamic specimen spelled out in a scene file",
          "[host][run][specimen][dynamics]") {
  TempDir dir;
  // tests/data/host/plexiglass_small.toml (20 x 20 points, h = 5 mm, eps = 20 mm) with the preset of
  // component/scenes/plexiglass_crack.cpp written as specimen variables: strips of grip boxes eps deep, the
  // top one held in x, the bottom one split at x = 0 and pulled apart at 1 m/s; the pre-crack up to 0.02 m
  // above the bottom face. The tip, -0.05 + 0.1/5 in double arithmetic, is -0.030000000000000002: it lies on
  // the midpoints of diagonal bonds across the crack line, so the last bit decides whether they are cut.
  const std::string small = PERISTEP_SOURCE_DIR "/tests/data/host/plexiglass_small.toml";
  std::string specimen = readText(small);
  const std::string step = "internalTimeStep = 0.0\n";  // the preset's: 001's 0.004 us
  REQUIRE(specimen.find(step) != std::string::npos);
  specimen.erase(specimen.find(step), step.size());
  const std::string scene = "scene = \"plexiglassCrack\"";
  REQUIRE(specimen.find(scene) != std::string::npos);
  const std::size_t n = 20 * 20;
  specimen.replace(specimen.find(scene), scene.size(),
                   "scene = \"specimen\"\nspecimenModel = \"dynamic\"\nnCracks = 1\nnGripBoxes = 3\n"
                   "materialYoungsModulus = " + tomlArray(std::vector<double>(n, 37.5e9)) +
                       "\ngripBottom = \"free\"\ngripTop = \"free\"\n"
                       "gripBoxHold = [\"heldX\", \"heldX\", \"heldX\"]\n"
                       "gripBoxX0 = [-0.05, -0.05, -0.00125]\ngripBoxX1 = [0.05, 0.00125, 0.05]\n"
                       "gripBoxY0 = [0.05, -0.07, -0.07]\ngripBoxY1 = [0.07, -0.05, -0.05]\n"
                       "gripBoxVx = [0.0, -1.0, 1.0]\n"
                       "crackX0 = [0.0]\ncrackY0 = [-0.07]\ncrackX1 = [0.0]\ncrackY1 = [-0.030000000000000002]\n"
                       "internalTimeStep = 0.004e-6");
  writeText(dir / "plexiglass_specimen.toml", specimen);
  const std::vector<std::string> preset = csvRows(dir, small, "preset");
  REQUIRE(preset.size() == 6);  // header and five steps
  REQUIRE(preset == csvRows(dir, (dir / "plexiglass_specimen.toml").string(), "specimen"));
}
