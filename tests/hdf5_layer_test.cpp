// The shared HDF5 layer (hdf5/hdf5_io.hpp): a round trip of what it writes, and its error paths, which
// throw hdf5::Error and leave no HDF5 identifier open behind them.
#include <catch2/catch.hpp>

#include <filesystem>

#include "hdf5_io.hpp"

using namespace peristep;

namespace {

std::string tempFile(const std::string& name) { return (std::filesystem::temp_directory_path() / name).string(); }

// Identifiers of every kind open in every file of the process (files included).
ssize_t openIdentifiers() { return H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL); }

}  // namespace

TEST_CASE("the HDF5 layer reads back what it writes", "[hdf5]") {
  const std::string path = tempFile("peristep_hdf5_layer_roundtrip.h5");
  const ssize_t before = openIdentifiers();
  {
    hdf5::Handle file = hdf5::createFile(path);
    hdf5::writeNumbers(file, "one", std::vector<double>{2.5});
    hdf5::writeNumbers(file, "many", std::vector<std::int64_t>{1, -2, 3});
    hdf5::writeString(file, "note", "text");
    const hdf5::Handle group = hdf5::createGroup(file, "a/b");
    const std::vector<double> values{1, 2, 3, 4, 5, 6};
    hdf5::writeDataset(group, "m", {2, 3}, values.data());
    file.close("close " + path);
  }
  {
    const hdf5::Handle file = hdf5::openFile(path);
    CHECK(hdf5::attributeNames(file) == std::vector<std::string>{"many", "note", "one"});
    CHECK(hdf5::readDouble(file, "one") == 2.5);
    CHECK(hdf5::linkNames(file) == std::vector<std::string>{"a"});
    const hdf5::Handle group = hdf5::openGroup(file, "a/b");
    const hdf5::Doubles m = hdf5::readDataset(group, "m");
    CHECK(m.shape == std::vector<std::uint64_t>{2, 3});
    CHECK(m.values == std::vector<double>{1, 2, 3, 4, 5, 6});
  }
  CHECK(openIdentifiers() == before);
  std::filesystem::remove(path);
}

TEST_CASE("the HDF5 layer's errors name what failed and leak no identifier", "[hdf5]") {
  const std::string path = tempFile("peristep_hdf5_layer_errors.h5");
  {
    hdf5::Handle file = hdf5::createFile(path);
    const hdf5::Handle group = hdf5::createGroup(file, "set");
    hdf5::writeNumbers(group, "pair", std::vector<double>{1, 2});
    file.close("close " + path);
  }
  const ssize_t before = openIdentifiers();
  {
    const hdf5::Handle file = hdf5::openFile(path);
    const ssize_t inFile = H5Fget_obj_count(file, H5F_OBJ_ALL);  // the file itself
    const hdf5::Handle group = hdf5::openGroup(file, "set");
    const ssize_t withGroup = H5Fget_obj_count(file, H5F_OBJ_ALL);
    CHECK(withGroup == inFile + 1);
    CHECK_THROWS_WITH(hdf5::readDataset(group, "missing"), "HDF5: cannot open dataset missing");
    CHECK_THROWS_AS(hdf5::readDataset(group, "missing"), hdf5::Error);
    CHECK_THROWS_WITH(hdf5::readDouble(group, "missing"), "HDF5: cannot open attribute missing");
    // Opened, then refused: the attribute's identifiers are closed on the way out too.
    CHECK_THROWS_WITH(hdf5::readDouble(group, "pair"), "HDF5: attribute pair is not a single number");
    CHECK_THROWS_AS(hdf5::openGroup(file, "missing"), hdf5::Error);
    // Written to a file opened read-only.
    const std::vector<double> one{1};
    CHECK_THROWS_AS(hdf5::writeDataset(group, "new", {1}, one.data()), hdf5::Error);
    CHECK(H5Fget_obj_count(file, H5F_OBJ_ALL) == withGroup);
  }
  CHECK(openIdentifiers() == before);
  CHECK_THROWS_WITH(hdf5::openFile(path + ".missing"), "HDF5: cannot open " + path + ".missing");
  CHECK(openIdentifiers() == before);
  std::filesystem::remove(path);
}
