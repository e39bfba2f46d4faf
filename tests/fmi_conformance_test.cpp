// modelDescription.xml keeps the FMI 3.0.2 rules beyond the schema (fmi_conformance_checker.cpp), and
// the checker finds each rule broken once in an otherwise conforming description.
#include <catch2/catch.hpp>
#include <functional>
#include <string>
#include <vector>

#include "fmi_conformance_checker.hpp"
#include "model_description_xml.hpp"

namespace {

std::string joined(const std::vector<std::string>& lines) {
  std::string s;
  for (const auto& l : lines) s += l + "\n";
  return s;
}

// The variable element named `name`.
xmlNodePtr variableNode(const XmlDocument& doc, const std::string& name) {
  for (xmlNodePtr v : children(firstChild(doc.root(), "ModelVariables")))
    if (attribute(v, "name") == name) return v;
  FAIL("no variable " << name);
  return nullptr;
}

void set(xmlNodePtr node, const char* name, const char* value) { xmlSetProp(node, BAD_CAST name, BAD_CAST value); }

}  // namespace

TEST_CASE("conformance: modelDescription.xml keeps the FMI 3.0.2 rules beyond the schema",
          "[modelDescription][conformance]") {
  for (const char* path : {PERISTEP_GENERATED_MODEL_DESCRIPTION, PERISTEP_COMMITTED_MODEL_DESCRIPTION}) {
    INFO(path);
    const XmlDocument doc(path);
    const auto found = conformanceViolations(doc.root());
    INFO(joined(found));
    CHECK(found.empty());
  }
}

// The checker itself: each rule, broken once in an otherwise conforming description, is reported.
TEST_CASE("conformance: the checker reports each broken rule", "[modelDescription][conformance]") {
  struct Breach {
    const char* rule;  // a piece of the expected message
    std::function<void(const XmlDocument&)> apply;
  };
  const std::vector<Breach> breaches{
      {"continuous only for Float32/Float64",
       [](const XmlDocument& d) { set(variableNode(d, "hasExactMoments"), "variability", "continuous"); }},
      {"variability/causality combination",
       [](const XmlDocument& d) { set(variableNode(d, "poissonRatio"), "variability", "continuous"); }},
      {"initial allowed for causality/variability",
       [](const XmlDocument& d) { set(variableNode(d, "poissonRatio"), "initial", "calculated"); }},
      {"start value not allowed", [](const XmlDocument& d) { set(variableNode(d, "ux"), "start", "0"); }},
      {"start value required",
       [](const XmlDocument& d) { xmlUnsetProp(variableNode(d, "loadFactor"), BAD_CAST "start"); }},
      {"start within [min, max]", [](const XmlDocument& d) { set(variableNode(d, "deltaOverH"), "start", "21"); }},
      {"enumeration start is an item value",
       [](const XmlDocument& d) { set(variableNode(d, "scene"), "start", "99"); }},
      {"declaredType defined",
       [](const XmlDocument& d) { set(variableNode(d, "scene"), "declaredType", "NoSuchType"); }},
      {"unit defined in <UnitDefinitions>",
       [](const XmlDocument& d) { set(variableNode(d, "Lx"), "unit", "furlong"); }},
      {"unit for every physical quantity",
       [](const XmlDocument& d) { xmlUnsetProp(variableNode(d, "toughnessKIC"), BAD_CAST "unit"); }},
      {"unique, non-empty names", [](const XmlDocument& d) { set(variableNode(d, "Ly"), "name", "Lx"); }},
      {"unique value references", [](const XmlDocument& d) { set(variableNode(d, "Ly"), "valueReference", "11"); }},
      {"references a UInt64 constant or structural parameter",
       [](const XmlDocument& d) {
         set(firstChild(variableNode(d, "xi"), "Dimension"), "valueReference", "11");  // Lx, a Float64
       }},
      {"structural parameter declared before its array",
       [](const XmlDocument& d) {
         xmlNodePtr nModes = variableNode(d, "nModes");
         xmlUnlinkNode(nModes);
         xmlAddNextSibling(variableNode(d, "xiScale"), nModes);
       }},
      {"every output listed as <Output>",
       [](const XmlDocument& d) {
         xmlNodePtr first = firstChild(firstChild(d.root(), "ModelStructure"), "Output");
         xmlUnlinkNode(first);
         xmlFreeNode(first);
       }},
      {"<Output> in the order of <ModelVariables>",
       [](const XmlDocument& d) {
         xmlNodePtr first = firstChild(firstChild(d.root(), "ModelStructure"), "Output");
         xmlNodePtr second = xmlNextElementSibling(first);
         xmlUnlinkNode(first);
         xmlAddNextSibling(second, first);
       }},
      {"dependencies are knowns",
       [](const XmlDocument& d) {
         set(firstChild(firstChild(d.root(), "ModelStructure"), "Output"), "dependencies", "41");  // uy, an output
         set(firstChild(firstChild(d.root(), "ModelStructure"), "Output"), "dependenciesKind", "dependent");
       }},
      {"every initial unknown listed",
       [](const XmlDocument& d) {
         xmlNodePtr first = firstChild(firstChild(d.root(), "ModelStructure"), "InitialUnknown");
         xmlUnlinkNode(first);
         xmlFreeNode(first);
       }},
  };
  for (const Breach& b : breaches) {
    INFO(b.rule);
    const XmlDocument doc(PERISTEP_GENERATED_MODEL_DESCRIPTION);
    b.apply(doc);
    const std::string found = joined(conformanceViolations(doc.root()));
    INFO(found);
    CHECK(found.find(b.rule) != std::string::npos);
  }
}
