// `peristep run` on a scene file that describes its own specimen (scene = "specimen"): the notched plate
// with the stiff inclusion of notched_plate.hpp, its material maps written into the file as arrays,
// cracks from the notch past the inclusion.
#include <catch2/catch.hpp>

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
