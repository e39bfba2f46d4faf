// `peristep run` without a scene runs scenes/default.toml: the compiled-in text is that file.
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

TEST_CASE("default scene: start values only, four increments of loadFactor up to 1", "[host][scene]") {
  const ModelDescription md = readModelDescription(PERISTEP_HOST_TEST_DATA "/modelDescription.xml");
  const Scene s = parseScene(defaultSceneText(), "default", md);
  CHECK(s.parameters.empty());  // Test 1 at nx = ny = 33 is what the FMU's start values say
  REQUIRE(s.loading.input.has_value());
  CHECK(s.loading.input->name == "loadFactor");
  CHECK(s.loading.from == 0.0);
  CHECK(s.loading.to == 1.0);
  CHECK(s.loading.steps == 4);
  CHECK(s.outputFile == "peristep_default.h5");
}
