// HDF5 and XDMF output without a component: a hand-made layout written step by step, read back
// with the HDF5 C API and libxml2; the partial-file protocol that keeps earlier results safe.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>

#include "host_errors.hpp"
#include "host_test_support.hpp"
#include "result_files.hpp"
#include "xdmf_writer.hpp"
#include "xml_test_support.hpp"

using namespace peristep::host;
using namespace host_test;

namespace {

// A 3 x 4 grid ([ny][nx]), two scalar outputs, one field, one ramped input.
ResultLayout smallLayout() {
  ResultLayout l;
  l.ny = 3;
  l.nx = 4;
  std::vector<double> x, y;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 4; ++i) x.push_back(i * 0.5), y.push_back(j * 0.5);
  l.constantArrays = {{"x", {3, 4}, "m", "point x"}, {"y", {3, 4}, "m", "point y"}};
  l.constantValues = {x, y};
  l.scalars = {{"errorL2", {}, "m", "L2 error"}, {"reactionForce", {}, "N/m", ""}};
  l.fields = {{"ux", {3, 4}, "m", "displacement x"}};
  l.inputName = "loadFactor";
  l.fileAttributes = {{"modelName", std::string("Test")}};
  l.parameterAttributes = {{"nx", std::vector<std::uint64_t>{4}},
                           {"poissonRatio", std::vector<double>{0.3}},
                           {"scene", std::string("smooth")},
                           {"xiDistribution", std::vector<std::int64_t>{0, 1}}};
  return l;
}

StepValues stepValues(int k) {
  StepValues s;
  s.time = 0.5 * k;
  s.input = 0.25 * k;
  s.scalars = {1e-3 * k, -2.0 * k};
  s.fields.assign(1, std::vector<double>(12));
  for (int i = 0; i < 12; ++i) s.fields[0][static_cast<std::size_t>(i)] = 100.0 * k + i;
  return s;
}

std::string attributeText(hid_t object, const char* name) {
  const hid_t a = H5Aopen(object, name, H5P_DEFAULT);
  const hid_t type = H5Aget_type(a);
  std::string s(H5Tget_size(type), '\0');
  H5Aread(a, type, s.data());
  H5Tclose(type);
  H5Aclose(a);
  return s.c_str();
}

double attributeNumber(hid_t object, const char* name) {
  const hid_t a = H5Aopen(object, name, H5P_DEFAULT);
  double v = NAN;
  H5Aread(a, H5T_NATIVE_DOUBLE, &v);
  H5Aclose(a);
  return v;
}

}  // namespace

TEST_CASE("results: HDF5 datasets, shapes, values and attributes", "[host][hdf5]") {
  TempDir dir;
  const ResultLayout layout = smallLayout();
  ResultFiles files(dir / "run.h5", layout);
  for (int k = 1; k <= 3; ++k) files.append(stepValues(k));
  files.commit();
  REQUIRE(fs::exists(dir / "run.h5"));
  REQUIRE(fs::exists(dir / "run.xmf"));
  CHECK_FALSE(fs::exists(dir / "run.partial.h5"));
  CHECK_FALSE(fs::exists(dir / "run.partial.xmf"));

  const hid_t f = openHdf5(dir / "run.h5");
  REQUIRE(f >= 0);
  const Dataset x = readDataset(f, "/grid/x");
  CHECK(x.shape == std::vector<hsize_t>{3, 4});
  CHECK(x.values[5] == 0.5);  // row 1, column 1
  CHECK(readDataset(f, "/time").values == std::vector<double>{0.5, 1.0, 1.5});
  CHECK(readDataset(f, "/inputs/loadFactor").values == std::vector<double>{0.25, 0.5, 0.75});
  CHECK(readDataset(f, "/scalars/errorL2").values == std::vector<double>{1e-3, 2e-3, 3e-3});
  CHECK(readDataset(f, "/scalars/reactionForce").values == std::vector<double>{-2, -4, -6});
  const Dataset ux = readDataset(f, "/fields/ux");
  CHECK(ux.shape == std::vector<hsize_t>{3, 3, 4});
  CHECK(ux.values[0] == 100.0);
  CHECK(ux.values[12 + 7] == 207.0);
  CHECK(ux.values[35] == 311.0);

  // Fields are chunked per step and compressed.
  const hid_t set = H5Dopen2(f, "/fields/ux", H5P_DEFAULT);
  const hid_t props = H5Dget_create_plist(set);
  CHECK(H5Pget_layout(props) == H5D_CHUNKED);
  bool deflate = false;
  for (int i = 0; i < H5Pget_nfilters(props); ++i) {
    unsigned flags = 0, config = 0;
    size_t n = 0;
    deflate |= H5Pget_filter2(props, static_cast<unsigned>(i), &flags, &n, nullptr, 0, nullptr, &config) == H5Z_FILTER_DEFLATE;
  }
  CHECK(deflate);
  CHECK(attributeText(set, "unit") == "m");
  H5Pclose(props);
  H5Dclose(set);

  CHECK(attributeText(f, "modelName") == "Test");
  const hid_t params = H5Gopen2(f, "/parameters", H5P_DEFAULT);
  CHECK(attributeNumber(params, "poissonRatio") == 0.3);
  CHECK(attributeNumber(params, "nx") == 4.0);
  CHECK(attributeText(params, "scene") == "smooth");
  H5Gclose(params);
  H5Fclose(f);
}

TEST_CASE("results: the XDMF parses and points at datasets that exist with the stated shapes", "[host][xdmf]") {
  TempDir dir;
  const ResultLayout layout = smallLayout();
  ResultFiles files(dir / "run.h5", layout);
  for (int k = 1; k <= 2; ++k) files.append(stepValues(k));
  files.commit();

  XmlDoc xmf(dir / "run.xmf");
  REQUIRE(xmf.doc);
  xmlNode* root = xmlDocGetRootElement(xmf.doc);
  CHECK(std::string(reinterpret_cast<const char*>(root->name)) == "Xdmf");
  std::vector<xmlNode*> grids, times, items, topologies;
  collect(root, "Grid", grids);
  collect(root, "Time", times);
  collect(root, "DataItem", items);
  collect(root, "Topology", topologies);
  REQUIRE(grids.size() == 3);  // the temporal collection and one grid per step
  CHECK(prop(grids[0], "CollectionType") == "Temporal");
  REQUIRE(times.size() == 2);
  CHECK(std::stod(prop(times[1], "Value")) == 1.0);
  CHECK(prop(topologies[0], "TopologyType") == "2DSMesh");
  CHECK(prop(topologies[0], "Dimensions") == "3 4");

  const hid_t f = openHdf5(dir / "run.h5");
  REQUIRE(f >= 0);
  int hdfItems = 0;
  for (xmlNode* item : items) {
    if (prop(item, "Format") != "HDF") continue;
    ++hdfItems;
    std::string text = content(item);
    text.erase(0, text.find_first_not_of(" \n"));
    text.erase(text.find_last_not_of(" \n") + 1);
    const auto colon = text.find(':');
    REQUIRE(colon != std::string::npos);
    CHECK(text.substr(0, colon) == "run.h5");  // relative to the .xmf: the pair can be moved together
    const Dataset d = readDataset(f, text.substr(colon + 1));
    REQUIRE_FALSE(d.shape.empty());
    std::string dims;
    for (hsize_t e : d.shape) {
      if (!dims.empty()) dims += ' ';
      dims += std::to_string(e);
    }
    CHECK(prop(item, "Dimensions") == dims);
  }
  // Per step: the geometry and the field; the input and the scalars are written inline.
  CHECK(hdfItems == 2 * 2);
  H5Fclose(f);

  // The views ParaView reads are the step's record and the interleaved coordinates.
  const hid_t g = openHdf5(dir / "run.h5");
  const Dataset ux2 = readDataset(g, xdmfFieldPath(1, "ux"));
  CHECK(ux2.shape == std::vector<hsize_t>{3, 4});
  CHECK(ux2.values == stepValues(2).fields[0]);
  const Dataset xy = readDataset(g, xdmfGeometryPath());
  CHECK(xy.shape == std::vector<hsize_t>{3, 4, 2});
  CHECK(xy.values[2 * 5] == 0.5);      // x of row 1, column 1
  CHECK(xy.values[2 * 11 + 1] == 1.0); // y of row 2
  H5Fclose(g);
  std::vector<xmlNode*> attributes;
  collect(root, "Attribute", attributes);
  REQUIRE(attributes.size() == 2 * 4);  // per step: ux, loadFactor, errorL2, reactionForce
  CHECK(prop(attributes[5], "Name") == "loadFactor");
  CHECK(prop(attributes[5], "Center") == "Grid");
  CHECK(std::stod(content(attributes[5])) == 0.5);
  CHECK(std::stod(content(attributes[7])) == -4.0);
}

TEST_CASE("results: a failing run leaves an earlier result untouched and keeps its finished steps",
          "[host][hdf5]") {
  TempDir dir;
  writeText(dir / "run.h5", "results of an earlier run");
  writeText(dir / "run.xmf", "its sidecar");
  const ResultLayout layout = smallLayout();

  SECTION("failure after two steps: both readable in the partial files") {
    ResultFiles files(dir / "run.h5", layout);
    files.append(stepValues(1));
    files.append(stepValues(2));
    const fs::path kept = files.abandon();
    CHECK(kept == dir / "run.partial.h5");
    const hid_t f = openHdf5(kept);
    REQUIRE(f >= 0);
    CHECK(readDataset(f, "/fields/ux").shape == std::vector<hsize_t>{2, 3, 4});
    H5Fclose(f);
    XmlDoc xmf(dir / "run.partial.xmf");
    CHECK(xmf.doc != nullptr);
    CHECK_THAT(readText(dir / "run.partial.xmf"), Catch::Matchers::Contains("run.partial.h5:" + xdmfFieldPath(1, "ux")));
  }
  SECTION("failure before the first step: nothing is left behind") {
    { ResultFiles files(dir / "run.h5", layout); }  // destroyed without commit
    CHECK_FALSE(fs::exists(dir / "run.partial.h5"));
    CHECK_FALSE(fs::exists(dir / "run.partial.xmf"));
  }
  CHECK(readText(dir / "run.h5") == "results of an earlier run");
  CHECK(readText(dir / "run.xmf") == "its sidecar");
}

TEST_CASE("results: a missing output directory is an input error", "[host][hdf5]") {
  TempDir dir;
  const ResultLayout layout = smallLayout();
  REQUIRE_THROWS_AS(ResultFiles(dir / "no" / "such" / "run.h5", layout), InputError);
  CHECK(partialName("out/run.h5") == fs::path("out/run.partial.h5"));
}

TEST_CASE("results: a step that does not match the layout is refused", "[host][hdf5]") {
  TempDir dir;
  const ResultLayout layout = smallLayout();
  ResultFiles files(dir / "run.h5", layout);
  StepValues bad = stepValues(1);
  bad.fields[0].pop_back();
  REQUIRE_THROWS_AS(files.append(bad), RunError);
}
