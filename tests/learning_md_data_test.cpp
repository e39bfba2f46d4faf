// The committed coarse-grained MD data (data/learning, made by scripts/md/generate.py) and its HDF5 layout.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>

#include "core/errors.hpp"
#include "hdf5_io.hpp"
#include "learning/coarse_data_file.hpp"

using namespace peristep::learning;

TEST_CASE("the committed MD data hold the sets of 003 Sec. 5 and the lattice constants", "[learning]") {
  const CoarseDataFile d = readCoarseData(std::string(PERISTEP_SOURCE_DIR) + "/data/learning/graphene_md.h5");
  REQUIRE(d.sets.count("train") == 1);
  CHECK(d.sets.at("train").samples.size() == 70);
  CHECK(d.sets.at("validation").samples.size() == 10);
  CHECK(d.sets.at("fracture_train").samples.size() == 41);
  CHECK(d.sets.at("fracture_test").samples.size() == 41);
  CHECK(d.sets.at("fracture_train_fine").grid.hx == Approx(3.17));
  CHECK(d.sets.at("fracture_train").frameInterval == Approx(4.95e-14));
  CHECK(d.constants.at("bond_length_A") == Approx(1.4606).epsilon(1e-4));
  CHECK(d.constants.at("C12_N_per_m") < 0);  // Tersoff 1988 carbon: negative Poisson ratio
  // Periodic static samples are self-equilibrated: the coarse-grained body force has no net force.
  for (const CoarseFields& f : d.sets.at("train").samples) {
    double net[2] = {0, 0}, size = 0;
    for (std::size_t p = 0; p < f.rho.size(); ++p)
      for (int c = 0; c < 2; ++c) net[c] += f.b[2 * p + c], size += std::abs(f.b[2 * p + c]);
    CHECK(std::abs(net[0]) < 1e-9 * size);
    CHECK(std::abs(net[1]) < 1e-9 * size);
  }
}

namespace {

CoarseDataFile smallCoarseData() {
  CoarseDataFile d;
  d.constants["C11_N_per_m"] = 417.757;
  CoarseDataSet set{CoarseGrid{2, 3, -1.0, -2.0, 0.5, 0.25, true}, 1e-3, 3.35, 5.0, {}};
  for (int s = 0; s < 2; ++s) {
    CoarseFields f;
    for (int p = 0; p < 6; ++p) {
      f.rho.push_back(1.0 + p + s);
      f.u.insert(f.u.end(), {0.1 * p, -0.2 * s});
      f.b.insert(f.b.end(), {1.5 * s, 2.5 * p});
    }
    set.samples.push_back(f);
  }
  d.sets["x"] = set;
  return d;
}

}  // namespace

TEST_CASE("coarse-grained data survive an HDF5 round trip, and a missing file is a precise error", "[learning]") {
  const CoarseDataFile d = smallCoarseData();
  const CoarseDataSet& set = d.sets.at("x");
  const std::string path = (std::filesystem::temp_directory_path() / "peristep_learning_roundtrip.h5").string();
  writeCoarseData(path, d);
  const CoarseDataFile r = readCoarseData(path);
  std::filesystem::remove(path);
  CHECK(r.constants.at("C11_N_per_m") == 417.757);
  const CoarseDataSet& x = r.sets.at("x");
  CHECK(x.grid.nx == 2);
  CHECK(x.grid.ny == 3);
  CHECK(x.grid.y0 == -2.0);
  CHECK(x.grid.periodic);
  CHECK(x.frameInterval == 1e-3);
  REQUIRE(x.samples.size() == 2);
  CHECK(x.samples[1].rho == set.samples[1].rho);
  CHECK(x.samples[1].u == set.samples[1].u);
  CHECK(x.samples[0].b == set.samples[0].b);
  CHECK_THROWS_AS(readCoarseData(path + ".missing"), peristep::InvalidInput);
}

TEST_CASE("coarse-grained data without a dataset of the layout are an HDF5 error that leaves nothing open",
          "[learning]") {
  const std::string path = (std::filesystem::temp_directory_path() / "peristep_learning_no_u.h5").string();
  writeCoarseData(path, smallCoarseData());
  {
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    REQUIRE(file >= 0);
    CHECK(H5Ldelete(file, "x/u", H5P_DEFAULT) >= 0);
    H5Fclose(file);
  }
  const ssize_t before = H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL);
  CHECK_THROWS_WITH(readCoarseData(path), "HDF5: cannot open dataset u");
  // The set's group and the file are closed on the way out (the group kept the file open before).
  CHECK(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL) == before);
  CHECK_THROWS_AS(readCoarseData(path), peristep::hdf5::Error);
  std::filesystem::remove(path);
}
