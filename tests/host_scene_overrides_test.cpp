// `--set name=value`: a [parameters] value given or replaced before the scene is read, the text read as
// the variable's type, with the same checks as a value in the file and messages that name the --set.
#include <catch2/catch.hpp>

#include "host_errors.hpp"
#include "scene_file.hpp"
#include "scene_overrides.hpp"

using namespace peristep::host;
using Catch::Matchers::Contains;

namespace {

const ModelDescription& model() {
  static const ModelDescription md = readModelDescription(PERISTEP_HOST_TEST_DATA "/modelDescription.xml");
  return md;
}

Scene withSets(const std::string& text, const std::vector<std::string>& sets) {
  std::vector<ParameterOverride> overrides;
  for (const std::string& s : sets) overrides.push_back(parseOverride(s));
  return parseScene(text, "scene.toml", model(), overrides);
}

std::string errorOf(const std::string& text, const std::vector<std::string>& sets) {
  try {
    withSets(text, sets);
  } catch (const InputError& e) {
    return e.what();
  }
  FAIL("no InputError for --set " << sets.front());
  return {};
}

template <class T>
std::vector<T> valuesOf(const Scene& s, const std::string& name) {
  const Setting* setting = s.setting(name);
  REQUIRE(setting);
  return std::get<std::vector<T>>(setting->values);
}

}  // namespace

TEST_CASE("scene overrides (--set): name=value split at the first '='", "[host][scene][set]") {
  CHECK(parseOverride("nx=9").name == "nx");
  CHECK(parseOverride(" nx = 9 ").value == "9");
  CHECK(parseOverride("a=b=c").value == "b=c");
  CHECK_THROWS_WITH(parseOverride("nx"), Contains("expected name=value"));
  CHECK_THROWS_WITH(parseOverride("=3"), Contains("the name is missing"));
}

TEST_CASE("scene overrides (--set): replaces a file's value or adds one, read as the variable's type", "[host][scene][set]") {
  const std::string file = "[parameters]\nnx = 5\nny = 5\nLx = 2.0\n";
  const Scene s = withSets(file, {"nx=9", "poissonRatio=0.25", "flag=true", "smallInt=-3", "scene=composite",
                                  "pair=[1.5, 2]", "Lx=3e-6"});
  CHECK(valuesOf<std::uint64_t>(s, "nx") == std::vector<std::uint64_t>{9});
  CHECK(valuesOf<std::uint64_t>(s, "ny") == std::vector<std::uint64_t>{5});  // left as the file says
  CHECK(valuesOf<double>(s, "poissonRatio") == std::vector<double>{0.25});
  CHECK(valuesOf<bool>(s, "flag") == std::vector<bool>{true});
  CHECK(valuesOf<std::int64_t>(s, "smallInt") == std::vector<std::int64_t>{-3});
  CHECK(valuesOf<std::int64_t>(s, "scene") == std::vector<std::int64_t>{2});
  CHECK(valuesOf<double>(s, "pair") == std::vector<double>{1.5, 2.0});
  CHECK(valuesOf<double>(s, "Lx") == std::vector<double>{3e-6});
  // A scene without [parameters] gets one; an array's length implies its structural parameter.
  const Scene bare = withSets("[loading]\nsteps = 2\n", {"xi=0.1, 0.2"});
  CHECK(valuesOf<double>(bare, "xi") == std::vector<double>{0.1, 0.2});
  CHECK(valuesOf<std::uint64_t>(bare, "nModes") == std::vector<std::uint64_t>{2});
  CHECK(bare.loading.steps == 2);
  // The last --set of a name wins.
  CHECK(valuesOf<std::uint64_t>(withSets(file, {"nx=7", "nx=8"}), "nx") == std::vector<std::uint64_t>{8});
}

TEST_CASE("scene overrides (--set): unknown names, unsettable variables and malformed values are refused", "[host][scene][set]") {
  const std::string file = "[parameters]\nnx = 5\n";
  CHECK_THAT(errorOf(file, {"nxx=9"}), Contains("--set nxx=9: unknown variable"));
  CHECK_THAT(errorOf(file, {"nxx=9"}), Contains("did you mean nx?"));
  CHECK_THAT(errorOf(file, {"x=1"}), Contains("--set x=1: x is a fixed calculatedParameter and cannot be set"));
  CHECK_THAT(errorOf(file, {"ux=1"}), Contains("cannot be set"));
  CHECK_THAT(errorOf(file, {"nx=five"}), Contains("--set nx=five: expected an integer for UInt64"));
  CHECK_THAT(errorOf(file, {"nx=-1"}), Contains("expected a non-negative integer"));
  CHECK_THAT(errorOf(file, {"nx=9.5"}), Contains("expected an integer"));
  CHECK_THAT(errorOf(file, {"Lx=wide"}), Contains("--set Lx=wide: expected a finite number for Float64"));
  CHECK_THAT(errorOf(file, {"Lx=inf"}), Contains("expected a finite number"));
  CHECK_THAT(errorOf(file, {"flag=maybe"}), Contains("expected true or false"));
  CHECK_THAT(errorOf(file, {"scene=cracked"}), Contains("unknown item \"cracked\" of Test.Scene"));
  CHECK_THAT(errorOf(file, {"pair=[1, x]"}), Contains("expected a finite number"));
  // Checked as a value in the file is: the range of the type, the length of an array.
  CHECK_THAT(errorOf(file, {"smallInt=4000000000"}), Contains("out of range for Int32"));
  CHECK_THAT(errorOf(file, {"pair=1, 2, 3"}), Contains("has 3 values but its shape [2] needs 2"));
}
