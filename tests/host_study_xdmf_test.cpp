// The XDMF file of a sample study: one grid per level (time = the level's sample count), the mean and
// standard deviation of every field read from datasets that exist in the study's HDF5 file with the
// stated shapes, on the interleaved coordinates.
#include <catch2/catch.hpp>

#include <set>

#include "host_test_support.hpp"
#include "xml_test_support.hpp"

using namespace host_test;

TEST_CASE("sample: the study's mean and std fields open through an XDMF file", "[host][sample][xdmf]") {
  TempDir dir;
  const ProcessResult r =
      runProcess({PERISTEP_HOST_BINARY, "sample", PERISTEP_SOURCE_DIR "/scenes/smooth_sampling.toml", "--rule", "tensor",
                  "--level", "1,2", "--set", "nx=9", "--set", "ny=9", "--out", "study.h5"},
                 dir.path());
  INFO(r.out << r.err);
  REQUIRE(r.exitCode == 0);
  CHECK_THAT(r.out, Catch::Matchers::Contains("wrote study.h5, study.xmf and study.csv"));

  XmlDoc xmf(dir / "study.xmf");
  REQUIRE(xmf.doc);
  xmlNode* root = xmlDocGetRootElement(xmf.doc);
  std::vector<xmlNode*> grids, times, items, attributes;
  collect(root, "Grid", grids);
  collect(root, "Time", times);
  collect(root, "DataItem", items);
  collect(root, "Attribute", attributes);
  REQUIRE(grids.size() == 3);  // the collection and one grid per level
  CHECK(prop(grids[0], "CollectionType") == "Temporal");
  REQUIRE(times.size() == 2);
  CHECK(prop(times[0], "Value") == "1");  // tensor level L has L samples in one coordinate
  CHECK(prop(times[1], "Value") == "2");
  std::set<std::string> names;
  for (xmlNode* a : attributes) names.insert(prop(a, "Name"));
  for (const char* name : {"mean_ux", "std_ux", "mean_damage", "std_uy", "mean_errorL2"}) CHECK(names.count(name) == 1);

  const hid_t f = openHdf5(dir / "study.h5");
  REQUIRE(f >= 0);
  std::size_t hdfItems = 0;
  for (xmlNode* item : items) {
    if (prop(item, "Format") != "HDF") continue;
    ++hdfItems;
    const std::string text = content(item);
    const auto colon = text.find(':');
    REQUIRE(colon != std::string::npos);
    CHECK(text.substr(0, colon) == "study.h5");
    const Dataset d = readDataset(f, text.substr(colon + 1));
    INFO(text);
    REQUIRE_FALSE(d.shape.empty());
    std::string dims;
    for (hsize_t e : d.shape) dims += (dims.empty() ? "" : " ") + std::to_string(e);
    CHECK(prop(item, "Dimensions") == dims);
  }
  CHECK(hdfItems > 2 * 4);
  // The geometry interleaves /grid/x and /grid/y.
  const Dataset xy = readDataset(f, "/xdmf/xy"), x = readDataset(f, "/grid/x"), y = readDataset(f, "/grid/y");
  REQUIRE(xy.shape == std::vector<hsize_t>{9, 9, 2});
  for (std::size_t k : {0u, 10u, 80u}) {
    CHECK(xy.values[2 * k] == x.values[k]);
    CHECK(xy.values[2 * k + 1] == y.values[k]);
  }
  H5Fclose(f);
}
