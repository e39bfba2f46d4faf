// `peristep run` end to end through the real FMU: the default scene (a glass-ceramic plate that
// cracks) and scenes/smooth.toml (Test 1, nx = ny = 33, four load increments) written to HDF5 and
// XDMF, read back with the HDF5 C API and libxml2; `peristep info` and --set.
#include <catch2/catch.hpp>

#include <libxml/parser.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "host_test_support.hpp"

using namespace host_test;
using Catch::Matchers::Contains;

namespace {

bool allFinite(const std::vector<double>& v) {
  return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
}

double readAttribute(hid_t object, const char* name) {
  const hid_t a = H5Aopen(object, name, H5P_DEFAULT);
  double v = NAN;
  H5Aread(a, H5T_NATIVE_DOUBLE, &v);
  H5Aclose(a);
  return v;
}

}  // namespace

TEST_CASE("peristep run: the default scene breaks bonds and grows a crack from the pre-crack", "[host][run]") {
  TempDir dir;
  const ProcessResult r = runProcess({PERISTEP_HOST_BINARY, "run"}, dir.path());
  INFO("stdout:\n" << r.out << "\nstderr:\n" << r.err);
  REQUIRE(r.exitCode == 0);
  CHECK_THAT(r.out, Contains("steps, 46 x 91 points), peristep_default.xmf, peristep_default.csv, "
                             "peristep_default.png and peristep_default_history.png"));
  for (const char* file : {"peristep_default.h5", "peristep_default.xmf", "peristep_default.csv",
                           "peristep_default.png", "peristep_default_history.png"})
    CHECK(fs::file_size(dir / file) > 0);

  const hid_t f = openHdf5(dir / "peristep_default.h5");
  REQUIRE(f >= 0);
  const Dataset broken = readDataset(f, "/scalars/brokenBonds"), crack = readDataset(f, "/scalars/crackLength");
  const Dataset load = readDataset(f, "/inputs/loadDisplacement"), damage = readDataset(f, "/fields/damage");
  H5Fclose(f);
  REQUIRE(broken.values.size() >= 2);
  REQUIRE(crack.values.size() == broken.values.size());
  constexpr std::size_t ny = 46, nx = 91;
  REQUIRE(damage.shape == std::vector<hsize_t>{broken.values.size(), ny, nx});
  CHECK(load.values.front() == Approx(8e-9));
  // The pre-crack's bonds are cut from the start; loading breaks many more, and the crack grows
  // from the tip at x = -300 um across most of the 800 um plate.
  CHECK(broken.values.front() > 0);
  CHECK(broken.values.back() > 5 * broken.values.front());
  CHECK(crack.values.front() == 0.0);
  CHECK(crack.values.back() > 400e-6);
  // Points on crack faces (damage >= 0.35) in the right half of the plate, far from the pre-crack.
  std::size_t cracked = 0;
  const std::size_t last = (broken.values.size() - 1) * ny * nx;
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = nx / 2 + 1; i < nx; ++i) cracked += damage.values[last + j * nx + i] >= 0.35;
  CHECK(cracked >= 20);

  // The CSV history says the same.
  std::istringstream csv(readText(dir / "peristep_default.csv"));
  std::string header, row, lastRow;
  std::getline(csv, header);
  while (std::getline(csv, row)) lastRow = row;
  std::istringstream h(header), v(lastRow);
  double brokenInCsv = -1;
  for (std::string key, value; std::getline(h, key, ',') && std::getline(v, value, ',');)
    if (key == "brokenBonds") brokenInCsv = std::stod(value);
  CHECK(brokenInCsv == broken.values.back());
}

TEST_CASE("peristep run scenes/smooth.toml: Test 1, the smooth manufactured solution", "[host][run]") {
  TempDir dir;
  const ProcessResult r = runProcess({PERISTEP_HOST_BINARY, "run", PERISTEP_SOURCE_DIR "/scenes/smooth.toml"}, dir.path());
  INFO("stdout:\n" << r.out << "\nstderr:\n" << r.err);
  REQUIRE(r.exitCode == 0);
  CHECK(r.err.empty());
  CHECK_THAT(r.out, Contains("wrote smooth.h5 (4 steps, 33 x 33 points)"));
  CHECK_THAT(r.out, Contains("errorL2"));

  const hid_t f = openHdf5(dir / "smooth.h5");
  REQUIRE(f >= 0);
  const Dataset x = readDataset(f, "/grid/x"), y = readDataset(f, "/grid/y");
  REQUIRE(x.shape == std::vector<hsize_t>{33, 33});
  REQUIRE(y.shape == std::vector<hsize_t>{33, 33});
  // [ny][nx] image order on [-1/2, 1/2]^2: x varies along a row, y down the rows.
  CHECK(x.values.front() == Approx(-0.5));
  CHECK(x.values[32] == Approx(0.5));
  CHECK(y.values[32] == Approx(-0.5));
  CHECK(y.values.back() == Approx(0.5));

  const Dataset time = readDataset(f, "/time"), load = readDataset(f, "/inputs/loadFactor");
  CHECK(time.values == std::vector<double>{0.25, 0.5, 0.75, 1.0});
  CHECK(load.values == std::vector<double>{0.25, 0.5, 0.75, 1.0});

  for (const char* field : {"/fields/ux", "/fields/uy", "/fields/damage"}) {
    const Dataset d = readDataset(f, field);
    INFO(field);
    CHECK(d.shape == std::vector<hsize_t>{4, 33, 33});
    CHECK(allFinite(d.values));
  }
  // The smooth scene cannot break; the displacement grows with the load.
  const Dataset damage = readDataset(f, "/fields/damage");
  CHECK(*std::max_element(damage.values.begin(), damage.values.end()) == 0.0);
  const Dataset ux = readDataset(f, "/fields/ux");
  const auto maxAbs = [&](std::size_t step) {
    double m = 0;
    for (std::size_t i = 0; i < 33 * 33; ++i) m = std::max(m, std::abs(ux.values[step * 33 * 33 + i]));
    return m;
  };
  CHECK(maxAbs(0) > 0);
  CHECK(maxAbs(3) == Approx(4 * maxAbs(0)).epsilon(1e-9));

  // Test 1 at h = 1/32: second-order small, and proportional to the load (the problem is linear).
  const Dataset error = readDataset(f, "/scalars/errorL2");
  REQUIRE(error.shape == std::vector<hsize_t>{4});
  REQUIRE(allFinite(error.values));
  CHECK(error.values[3] > 0);
  CHECK(error.values[3] < 1e-3);
  for (std::size_t k = 0; k < 4; ++k) CHECK(error.values[k] == Approx(load.values[k] * error.values[3]).epsilon(1e-6));
  for (const char* scalar : {"reactionForce", "crackLength", "brokenBonds", "strainEnergy", "fractureEnergy", "toughnessKIC"})
    CHECK(readDataset(f, std::string("/scalars/") + scalar).shape == std::vector<hsize_t>{4});

  const hid_t params = H5Gopen2(f, "/parameters", H5P_DEFAULT);
  REQUIRE(params >= 0);
  CHECK(readAttribute(params, "nx") == 33.0);
  CHECK(readAttribute(params, "poissonRatio") == 0.3);
  CHECK(readAttribute(params, "deltaOverH") == 3.0);
  H5Gclose(params);
  H5Fclose(f);

  xmlDoc* xmf = xmlReadFile((dir / "smooth.xmf").c_str(), nullptr, XML_PARSE_NONET);
  REQUIRE(xmf != nullptr);
  CHECK(std::string(reinterpret_cast<const char*>(xmlDocGetRootElement(xmf)->name)) == "Xdmf");
  xmlFreeDoc(xmf);
  const std::string xmfText = readText(dir / "smooth.xmf");
  CHECK_THAT(xmfText, Contains("smooth.h5:/xdmf/step_4/damage"));
  CHECK_THAT(xmfText, Contains("<Time Value=\"1\"/>"));
  CHECK_FALSE(fs::exists(dir / "smooth.partial.h5"));
}

TEST_CASE("peristep run: a scene file, --fmu and --out", "[host][run]") {
  TempDir dir;
  writeText(dir / "coarse.toml", R"(
[parameters]
nx = 9
ny = 9
poissonRatio = 0.25
[loading]
input = "loadFactor"
from = 0.0
to = 2.0
steps = 2
)");
  const ProcessResult r =
      runProcess({PERISTEP_HOST_BINARY, "run", "coarse.toml", "--fmu", PERISTEP_FMU, "--out", "c.h5"}, dir.path());
  INFO(r.err);
  REQUIRE(r.exitCode == 0);
  const hid_t f = openHdf5(dir / "c.h5");
  REQUIRE(f >= 0);
  CHECK(readDataset(f, "/fields/ux").shape == std::vector<hsize_t>{2, 9, 9});
  CHECK(readDataset(f, "/inputs/loadFactor").values == std::vector<double>{1.0, 2.0});
  const hid_t params = H5Gopen2(f, "/parameters", H5P_DEFAULT);
  CHECK(readAttribute(params, "poissonRatio") == 0.25);
  H5Gclose(params);
  H5Fclose(f);
  CHECK(fs::exists(dir / "c.xmf"));
}

TEST_CASE("peristep info: every variable with causality, type and unit", "[host][info]") {
  TempDir dir;
  const ProcessResult r = runProcess({PERISTEP_HOST_BINARY, "info", PERISTEP_FMU}, dir.path());
  REQUIRE(r.exitCode == 0);
  for (const char* line : {"poissonRatio", "structuralParameter", "calculatedParameter", "loadFactor", "errorL2",
                           "ux[ny][nx]", "xi[nModes]", "PeriStep.Scene", "smooth", "N/m"})
    CHECK_THAT(r.out, Contains(line));
}

// 003's prediction through the host: scenes/learned_fracture.toml runs sample III from the FMU's resources
// (unpacked from PeriStep.fmu with the rest) and its CSV ends with the errors over frames 1-40 that
// bench/learn_predict prints with the learned s0 (14.5% / 36.1%, docs/verification.md).
TEST_CASE("peristep run scenes/learned_fracture.toml: the learned model's errors against 40 MD frames",
          "[host][run][learned]") {
  TempDir dir;
  const ProcessResult r = runProcess(
      {PERISTEP_HOST_BINARY, "run", PERISTEP_SOURCE_DIR "/scenes/learned_fracture.toml", "--fmu", PERISTEP_FMU, "--out",
       "lf.h5"},
      dir.path());
  INFO(r.err);
  REQUIRE(r.exitCode == 0);
  std::istringstream csv(readText(dir / "lf.csv"));
  std::string header, line, last;
  std::getline(csv, header);
  std::size_t rows = 0;
  while (std::getline(csv, line)) last = line, ++rows;
  CHECK(rows == 40);
  const auto column = [&](const std::string& name) {
    std::istringstream h(header), v(last);
    for (std::string key, value; std::getline(h, key, ',') && std::getline(v, value, ',');)
      if (key == name) return std::stod(value);
    FAIL("no column " << name);
    return 0.0;
  };
  CHECK(column("predictionErrorDisplacement") == Approx(0.145).epsilon(3e-3));
  CHECK(column("predictionErrorDamage") == Approx(0.361).epsilon(3e-3));
}
