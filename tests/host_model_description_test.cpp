// The host reads a model description with libxml2: everything it maps scene names through, and a
// precise error for a file it cannot use.
#include <catch2/catch.hpp>

#include "host_errors.hpp"
#include "model_description.hpp"

using namespace peristep::host;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

const std::string kTestModel = PERISTEP_HOST_TEST_DATA "/modelDescription.xml";

std::string minimal(const std::string& variables) {
  return R"(<?xml version="1.0"?>
<fmiModelDescription fmiVersion="3.0" modelName="M" instantiationToken="t">
  <ModelVariables>)" +
         variables + R"(</ModelVariables>
</fmiModelDescription>)";
}

}  // namespace

TEST_CASE("model description: header, experiment, categories", "[host][model_description]") {
  const ModelDescription md = readModelDescription(kTestModel);
  CHECK(md.fmiVersion == "3.0");
  CHECK(md.modelName == "TestModel");
  CHECK(md.instantiationToken == "{00000000-0000-0000-0000-000000000001}");
  CHECK(md.coSimulationIdentifier == "TestModel");
  CHECK(md.generationTool == "hand-made");
  CHECK(md.defaultExperiment.startTime == 0.0);
  CHECK(md.defaultExperiment.stopTime == 2.0);
  CHECK(md.defaultExperiment.stepSize == 0.5);
  CHECK_FALSE(md.defaultExperiment.tolerance.has_value());
  CHECK(md.logCategories == std::vector<std::string>{"logStatusError", "logEvents"});
}

TEST_CASE("model description: variables with type, causality, unit, dimensions", "[host][model_description]") {
  const ModelDescription md = readModelDescription(kTestModel);
  REQUIRE(md.variables.size() == 16);

  const Variable* nx = md.find("nx");
  REQUIRE(nx);
  CHECK(nx->valueReference == 1);
  CHECK(nx->type == VarType::UInt64);
  CHECK(nx->causality == Causality::StructuralParameter);
  CHECK(nx->variability == Variability::Fixed);
  CHECK(nx->start == "33");

  const Variable* lx = md.find("Lx");
  REQUIRE(lx);
  CHECK(lx->unit == "m");  // inherited from its declared type Length
  CHECK(lx->description == "domain width");

  const Variable* ux = md.find("ux");
  REQUIRE(ux);
  CHECK(ux->causality == Causality::Output);
  CHECK(ux->variability == Variability::Continuous);
  REQUIRE(ux->dimensions.size() == 2);
  CHECK(ux->dimensions[0].valueReference == 2u);  // [ny][nx]: ny first
  CHECK(ux->dimensions[1].valueReference == 1u);

  const Variable* pair = md.find("pair");
  REQUIRE(pair);
  REQUIRE(pair->dimensions.size() == 1);
  CHECK(pair->dimensions[0].start == 2u);
  CHECK(pair->start == "1 2");

  // FMI 3.0 default variability: continuous for floats, discrete for the rest.
  CHECK(md.find("time")->causality == Causality::Independent);
  CHECK(md.findByValueReference(56)->name == "errorL2");
  CHECK(md.find("nonexistent") == nullptr);
}

TEST_CASE("model description: enumerations", "[host][model_description]") {
  const ModelDescription md = readModelDescription(kTestModel);
  const Variable* scene = md.find("scene");
  REQUIRE(scene);
  CHECK(scene->type == VarType::Enumeration);
  const EnumerationType* e = md.enumeration(scene->declaredType);
  REQUIRE(e);
  REQUIRE(e->items.size() == 2);
  CHECK(e->itemNamed("composite")->value == 2);
  CHECK(e->itemValued(1)->name == "smooth");
  CHECK(e->itemValued(1)->description == "smooth manufactured solution");
  CHECK(e->itemNamed("rough") == nullptr);
}

TEST_CASE("model description: defaults of omitted attributes", "[host][model_description]") {
  const ModelDescription md =
      parseModelDescription(minimal(R"(<Float64 name="a" valueReference="1"/><Int32 name="b" valueReference="2"/>)"), "m.xml");
  CHECK(md.find("a")->causality == Causality::Local);
  CHECK(md.find("a")->variability == Variability::Continuous);
  CHECK(md.find("b")->variability == Variability::Discrete);
  CHECK(md.coSimulationIdentifier.empty());
}

TEST_CASE("model description: unusable files are refused with file and reason", "[host][model_description]") {
  REQUIRE_THROWS_WITH(readModelDescription("/nonexistent/modelDescription.xml"),
                      StartsWith("/nonexistent/modelDescription.xml: cannot open"));
  REQUIRE_THROWS_WITH(parseModelDescription("<fmiModelDescription", "broken.xml"),
                      StartsWith("broken.xml:") && Contains("not well-formed"));
  REQUIRE_THROWS_WITH(parseModelDescription("<other/>", "x.xml"), Contains("not <fmiModelDescription>"));
  REQUIRE_THROWS_WITH(
      parseModelDescription(R"(<fmiModelDescription fmiVersion="2.0" modelName="M" instantiationToken="t"/>)", "x.xml"),
      Contains("expected 3.x"));
  REQUIRE_THROWS_WITH(parseModelDescription(minimal(R"(<Float64 name="a"/>)"), "x.xml"),
                      Contains("lacks the attribute valueReference"));
  REQUIRE_THROWS_WITH(parseModelDescription(minimal(R"(<Float64 name="a" valueReference="x1"/>)"), "x.xml"),
                      Contains("not a valid number"));
  REQUIRE_THROWS_WITH(
      parseModelDescription(minimal(R"(<Float64 name="a" valueReference="1"/><Float64 name="b" valueReference="1"/>)"), "x.xml"),
      Contains("value reference 1 is used by both a and b"));
  REQUIRE_THROWS_WITH(
      parseModelDescription(
          minimal(R"(<Float64 name="n" valueReference="1"/>
                     <Float64 name="a" valueReference="2"><Dimension valueReference="1"/></Float64>)"),
          "x.xml"),
      Contains("no structural parameter"));
  REQUIRE_THROWS_WITH(parseModelDescription(minimal(R"(<Enumeration name="e" valueReference="1" declaredType="T"/>)"), "x.xml"),
                      Contains("unknown declaredType"));
  REQUIRE_THROWS_AS(parseModelDescription(minimal(R"(<Float64 name="a" valueReference="1" causality="sideways"/>)"), "x.xml"),
                    InputError);
}
