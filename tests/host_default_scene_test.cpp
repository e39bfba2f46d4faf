// `peristep run` without a scene runs scenes/default.toml (the compiled-in text is that file): a
// glass-ceramic plate that cracks; Test 1, the default before it, is scenes/smooth.toml.
#include <catch2/catch.hpp>

#include "default_scene.hpp"
#include "host_test_support.hpp"
#include "scene_file.hpp"

using namespace peristep::host;

TEST_CASE("default scene: the compiled-in text is scenes/default.toml", "[host][scene]") {
  const std::string file = host_test::readText(PERISTEP_SOURCE_DIR "/scenes/default.toml");
  REQUIRE_FALSE(file.empty());
  CHECK(std::string(defaultSceneText()) == file);
}

TEST_CASE("default scene: the glass-ceramic plate at h = 8.9 um, opened to 0.32 um in 40 increments", "[host][scene]") {
  const ModelDescription md = readModelDescription(PERISTEP_SOURCE_DIR "/modelDescription/modelDescription.xml");
  const Scene s = parseScene(defaultSceneText(), "default", md);
  REQUIRE(s.setting("scene") != nullptr);
  CHECK(describeValues(*s.setting("scene"), md) == "glassCeramic");
  CHECK(std::get<std::vector<std::uint64_t>>(s.setting("nx")->values) == std::vector<std::uint64_t>{91});
  CHECK(std::get<std::vector<std::uint64_t>>(s.setting("ny")->values) == std::vector<std::uint64_t>{46});
  // The same spacing in x and y: Lx / (nx - 1) = Ly / (ny - 1) = 8.9 um.
  const double lx = std::get<std::vector<double>>(s.setting("Lx")->values).front();
  const double ly = std::get<std::vector<double>>(s.setting("Ly")->values).front();
  CHECK(lx / 90 == Approx(ly / 45));
  CHECK(lx / 90 == Approx(8.889e-6).epsilon(1e-3));
  REQUIRE(s.loading.input.has_value());
  CHECK(s.loading.input->name == "loadDisplacement");
  CHECK(s.loading.from == 0.0);
  CHECK(s.loading.to == 0.32e-6);
  CHECK(s.loading.steps == 40);
  CHECK(s.outputFile == "peristep_default.h5");
}

TEST_CASE("scenes/smooth.toml: Test 1 from the start values, four increments of loadFactor up to 1", "[host][scene]") {
  const ModelDescription md = readModelDescription(PERISTEP_SOURCE_DIR "/modelDescription/modelDescription.xml");
  const Scene s = readScene(PERISTEP_SOURCE_DIR "/scenes/smooth.toml", md);
  CHECK(s.parameters.empty());  // Test 1 at nx = ny = 33 is what the FMU's start values say
  REQUIRE(s.loading.input.has_value());
  CHECK(s.loading.input->name == "loadFactor");
  CHECK(s.loading.from == 0.0);
  CHECK(s.loading.to == 1.0);
  CHECK(s.loading.steps == 4);
  CHECK(s.outputFile == "smooth.h5");
}
