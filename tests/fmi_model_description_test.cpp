// modelDescription.xml against the component's variable table, the committed copy and the FMI 3.0
// schema; and the table's own consistency.
#include <libxml/xmlschemas.h>

#include <catch2/catch.hpp>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

#include "fmi/model_binding.hpp"
#include "fmi/parameter_values.hpp"
#include "fmi/variables.hpp"
#include "model_description_xml.hpp"
#include "peristep.h"

using namespace peristep::fmi;

namespace {

std::string readFile(const char* path) {
  std::ifstream in(path, std::ios::binary);
  REQUIRE(in);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The only child element of that name.
xmlNodePtr child(xmlNodePtr node, const char* name) {
  const auto all = children(node, name);
  REQUIRE(all.size() == 1);
  return all.front();
}

void collectSchemaError(void* context, const char* format, ...) {
  char buffer[1024];
  va_list args;
  va_start(args, format);
  std::vsnprintf(buffer, sizeof buffer, format, args);
  va_end(args);
  *static_cast<std::string*>(context) += buffer;
}

}  // namespace

TEST_CASE("the committed modelDescription.xml is the generated one", "[modelDescription]") {
  INFO("regenerate the copy: cp <build>/modelDescription.xml modelDescription/modelDescription.xml");
  CHECK(readFile(PERISTEP_COMMITTED_MODEL_DESCRIPTION) == readFile(PERISTEP_GENERATED_MODEL_DESCRIPTION));
}

TEST_CASE("the committed docs/variables.md is the generated variable reference", "[modelDescription]") {
  INFO("regenerate it: cp <build>/variables.md docs/variables.md");
  CHECK(readFile(PERISTEP_COMMITTED_VARIABLE_REFERENCE) == readFile(PERISTEP_GENERATED_VARIABLE_REFERENCE));
}

TEST_CASE("the committed api/peristep.h is the generated one", "[modelDescription]") {
  INFO("regenerate it: cp <build>/peristep.h api/peristep.h");
  CHECK(readFile(PERISTEP_COMMITTED_API_HEADER) == readFile(PERISTEP_GENERATED_API_HEADER));
}

TEST_CASE("modelDescription.xml names its author, copyright, licence, tool and date", "[modelDescription]") {
  const XmlDocument doc(PERISTEP_GENERATED_MODEL_DESCRIPTION);
  for (const char* name : {"author", "copyright", "license", "generationTool", "version"}) {
    INFO(name);
    CHECK(attribute(doc.root(), name).size() > 3);
  }
  // xs:dateTime as FMI 3.0 asks for it, in UTC.
  const std::string date = attribute(doc.root(), "generationDateAndTime");
  CHECK(date.size() == 20);
  CHECK(date[4] == '-');
  CHECK(date[10] == 'T');
  CHECK(date.back() == 'Z');
}

TEST_CASE("modelDescription.xml validates against the FMI 3.0 schema", "[modelDescription]") {
  const char* schemaPath = PERISTEP_FMI3_SCHEMA;
  if (!std::filesystem::exists(schemaPath)) {
    // CI has the schema: there a missing schema is a failure, never a silent pass.
    if (std::getenv("CI")) FAIL("FMI 3.0 schema not found at " << schemaPath << " (CI is set)");
    std::cout << "SKIPPED: FMI 3.0 schema not found at " << schemaPath << " (set PERISTEP_FMI3_SCHEMA_DIR)\n";
    return;
  }
  std::string errors;
  xmlSchemaParserCtxtPtr parser = xmlSchemaNewParserCtxt(schemaPath);
  REQUIRE(parser != nullptr);
  xmlSchemaSetParserErrors(parser, collectSchemaError, collectSchemaError, &errors);
  xmlSchemaPtr schema = xmlSchemaParse(parser);
  xmlSchemaFreeParserCtxt(parser);
  INFO(errors);
  REQUIRE(schema != nullptr);
  for (const char* path : {PERISTEP_GENERATED_MODEL_DESCRIPTION, PERISTEP_COMMITTED_MODEL_DESCRIPTION}) {
    INFO(path);
    XmlDocument doc(path);
    xmlSchemaValidCtxtPtr validator = xmlSchemaNewValidCtxt(schema);
    xmlSchemaSetValidErrors(validator, collectSchemaError, collectSchemaError, &errors);
    const int result = xmlSchemaValidateDoc(validator, doc.doc);
    xmlSchemaFreeValidCtxt(validator);
    INFO(errors);
    CHECK(result == 0);
  }
  xmlSchemaFree(schema);
}

TEST_CASE("the variables of the table and of modelDescription.xml are the same", "[modelDescription]") {
  XmlDocument doc(PERISTEP_GENERATED_MODEL_DESCRIPTION);
  std::map<fmi3ValueReference, xmlNodePtr> xml;
  std::vector<fmi3ValueReference> order;
  for (xmlNodePtr v : children(child(doc.root(), "ModelVariables"))) {
    const auto vr = static_cast<fmi3ValueReference>(std::stoul(attribute(v, "valueReference")));
    CHECK(xml.emplace(vr, v).second);  // unique value references
    order.push_back(vr);
  }
  CHECK(xml.size() == variables().size());
  std::vector<fmi3ValueReference> tableOrder;
  for (const Variable& v : variables()) {
    INFO(label(v));
    tableOrder.push_back(v.vr);
    const auto it = xml.find(v.vr);
    REQUIRE(it != xml.end());
    xmlNodePtr node = it->second;
    CHECK(attribute(node, "name") == v.name);
    CHECK(reinterpret_cast<const char*>(node->name) == typeName(v.type));
    CHECK(attribute(node, "causality") == causalityName(v.causality));
    CHECK(attribute(node, "variability") == variabilityName(v.variability));
    CHECK(attribute(node, "declaredType") == v.declaredType);
    CHECK(attribute(node, "unit") == v.unit);
    std::vector<fmi3ValueReference> dims;
    for (xmlNodePtr d : children(node, "Dimension"))
      dims.push_back(static_cast<fmi3ValueReference>(std::stoul(attribute(d, "valueReference"))));
    CHECK(dims == v.dimensions);
    CHECK(attribute(node, "start").empty() == v.start.empty());
  }
  CHECK(order == tableOrder);

  // Every output is an <Output>; outputs and calculated parameters are the initial unknowns.
  xmlNodePtr structure = child(doc.root(), "ModelStructure");
  std::set<fmi3ValueReference> outputs, initial, expectOutputs, expectInitial;
  for (xmlNodePtr o : children(structure, "Output")) {
    const Variable* v = findVariable(std::stoul(attribute(o, "valueReference")));
    REQUIRE(v != nullptr);
    outputs.insert(v->vr);
    // <Output dependencies> are the table's (absent where the table leaves them unset).
    INFO(label(*v));
    std::string deps;
    for (fmi3ValueReference d : v->dependencies.value_or(std::vector<fmi3ValueReference>{}))
      deps.append(deps.empty() ? "" : " ").append(std::to_string(d));
    CHECK((xmlHasProp(o, BAD_CAST "dependencies") != nullptr) == v->dependencies.has_value());
    CHECK(attribute(o, "dependencies") == deps);
  }
  for (xmlNodePtr o : children(structure, "InitialUnknown")) initial.insert(std::stoul(attribute(o, "valueReference")));
  for (const Variable& v : variables()) {
    if (v.causality == Causality::Output) expectOutputs.insert(v.vr);
    if (v.causality == Causality::Output || v.causality == Causality::CalculatedParameter) expectInitial.insert(v.vr);
  }
  CHECK(outputs == expectOutputs);
  CHECK(initial == expectInitial);

  // The FMU identity the library checks.
  CHECK(attribute(doc.root(), "instantiationToken") == PERISTEP_INSTANTIATION_TOKEN);
  CHECK(attribute(doc.root(), "fmiVersion") == "3.0");
  xmlNodePtr cs = child(doc.root(), "CoSimulation");
  CHECK(attribute(cs, "modelIdentifier") == "PeriStep");
  CHECK(attribute(cs, "canGetAndSetFMUState") == "true");
  CHECK(attribute(cs, "canSerializeFMUState") == "true");
  xmlNodePtr experiment = child(doc.root(), "DefaultExperiment");
  CHECK(attribute(experiment, "stepSize") == "0.25");
}

TEST_CASE("the variable table is consistent", "[modelDescription]") {
  std::set<std::string_view> names;
  std::set<fmi3ValueReference> seen;
  for (const Variable& v : variables()) {
    INFO(label(v));
    CHECK(names.insert(v.name).second);
    CHECK(seen.insert(v.vr).second);
    // Dimensions name structural parameters (UInt64 scalars) declared earlier (FMI 3.0 Sec. 2.4.7.1).
    for (fmi3ValueReference d : v.dimensions) {
      const Variable* s = findVariable(d);
      REQUIRE(s != nullptr);
      CHECK(s->causality == Causality::StructuralParameter);
      CHECK(s->type == VarType::UInt64);
      CHECK(s->dimensions.empty());
      CHECK(seen.count(d) == 1);
    }
    CHECK((v.type == VarType::Enumeration) == !v.declaredType.empty());
    if (v.type == VarType::Enumeration) CHECK(findEnumeration(v.declaredType) != nullptr);
    // Settable variables have a start value; computed ones have a reader of their type.
    const ComputedVariable* c = findComputed(v.vr);
    if (v.causality == Causality::CalculatedParameter || v.causality == Causality::Output) {
      REQUIRE(c != nullptr);
      CHECK((c->readFloat64 != nullptr) == (v.type == VarType::Float64));
      CHECK((c->readInt32 != nullptr) == (v.type == VarType::Int32));
      CHECK(v.start.empty());
    } else {
      CHECK(c == nullptr);
      CHECK(v.start.empty() == (v.causality == Causality::Independent));
    }
  }
  // Every start value parses and lies in its variable's range.
  const ParameterValues start;
  for (const Variable& v : variables())
    if (settable(v) && v.type == VarType::Float64) CHECK_NOTHROW(start.check(v, start.get<double>(v.vr)));
}
