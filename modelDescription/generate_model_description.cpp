// Writes modelDescription.xml from the component's variable table (component/fmi/variables.hpp),
// so that the description and the binary cannot disagree.
//
//   generate_model_description <output.xml>
#include <libxml/xmlwriter.h>

#include <charconv>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "fmi/log_categories.hpp"
#include "fmi/variables.hpp"
#include "model_summary.hpp"
#include "fmi/model_identity.hpp"

using namespace peristep::fmi;

namespace {

// Wraps libxml2's text writer; every failed write throws.
class Writer {
 public:
  explicit Writer(const char* path) : w_(xmlNewTextWriterFilename(path, 0)) {
    if (!w_) throw std::runtime_error(std::string("cannot open ") + path);
    check(xmlTextWriterSetIndent(w_, 1));
    check(xmlTextWriterSetIndentString(w_, BAD_CAST "  "));
    check(xmlTextWriterStartDocument(w_, nullptr, "UTF-8", nullptr));
  }
  ~Writer() { xmlFreeTextWriter(w_); }
  Writer(const Writer&) = delete;
  Writer& operator=(const Writer&) = delete;

  void start(const char* element) { check(xmlTextWriterStartElement(w_, BAD_CAST element)); }
  void end() { check(xmlTextWriterEndElement(w_)); }
  void attribute(const char* name, std::string_view value) {
    const std::string v(value);
    check(xmlTextWriterWriteAttribute(w_, BAD_CAST name, BAD_CAST v.c_str()));
  }
  void finish() { check(xmlTextWriterEndDocument(w_)); }

 private:
  static void check(int rc) {
    if (rc < 0) throw std::runtime_error("libxml2 could not write the model description");
  }
  xmlTextWriterPtr w_;
};

std::uint64_t startOf(fmi3ValueReference structural) {
  const Variable& v = *findVariable(structural);
  std::uint64_t n = 0;
  std::from_chars(v.start.data(), v.start.data() + v.start.size(), n);
  return n;
}

// The table gives one start value per variable; an array lists it once per element (at the
// structural parameters' start values).
std::string startList(const Variable& v) {
  std::uint64_t n = 1;
  for (fmi3ValueReference d : v.dimensions) n *= startOf(d);
  std::string s;
  for (std::uint64_t k = 0; k < n; ++k) {
    if (k) s += ' ';
    s += v.start;
  }
  return s;
}

void writeVariable(Writer& w, const Variable& v) {
  const std::string element(typeName(v.type));  // the XML element is named after the type
  w.start(element.c_str());
  w.attribute("name", v.name);
  w.attribute("valueReference", std::to_string(v.vr));
  w.attribute("description", v.description);
  w.attribute("causality", causalityName(v.causality));
  w.attribute("variability", variabilityName(v.variability));
  if (v.initial != Initial::Default) w.attribute("initial", v.initial == Initial::Exact ? "exact" : "calculated");
  if (!v.declaredType.empty()) w.attribute("declaredType", v.declaredType);
  if (!v.unit.empty()) w.attribute("unit", v.unit);
  // XML bounds are inclusive: open ends are stated in the description instead.
  if (v.min && !v.min->open) w.attribute("min", number(v.min->value));
  if (v.max && !v.max->open) w.attribute("max", number(v.max->value));
  if (!v.start.empty()) w.attribute("start", startList(v));
  for (fmi3ValueReference d : v.dimensions) {
    w.start("Dimension");
    w.attribute("valueReference", std::to_string(d));
    w.end();
  }
  w.end();
}

void writeModelDescription(const char* path) {
  Writer w(path);
  w.start("fmiModelDescription");
  w.attribute("fmiVersion", "3.0");
  w.attribute("modelName", "PeriStep");
  w.attribute("instantiationToken", kInstantiationToken);
  w.attribute("description", kModelSummary);
  w.attribute("version", PERISTEP_VERSION);
  w.attribute("author", "The PeriStep developers");
  w.attribute("copyright", "Copyright (C) 2026 The PeriStep developers");
  w.attribute("license",
              "GPL-2.0-or-later; the FMU bundles SuiteSparse's UMFPACK and CHOLMOD (GPL-2+) and other libraries "
              "whose licences are in documentation/licenses/");
  w.attribute("generationTool", "PeriStep generate_model_description " PERISTEP_VERSION);
  // A fixed date per version, not the build's clock: builds stay reproducible and the committed copy
  // of this file identical to the generated one.
  w.attribute("generationDateAndTime", PERISTEP_MODEL_DATE);
  w.attribute("variableNamingConvention", "flat");

  w.start("CoSimulation");
  w.attribute("modelIdentifier", kModelIdentifier);
  w.attribute("canBeInstantiatedOnlyOncePerProcess", "false");
  w.attribute("canGetAndSetFMUState", "true");
  w.attribute("canSerializeFMUState", "true");
  w.attribute("canHandleVariableCommunicationStepSize", "true");
  w.attribute("hasEventMode", "false");
  w.end();

  w.start("UnitDefinitions");
  for (const UnitDefinition& u : unitDefinitions()) {
    w.start("Unit");
    w.attribute("name", u.name);
    if (u.integerPowers) {
      w.start("BaseUnit");
      if (u.kg) w.attribute("kg", std::to_string(u.kg));
      if (u.m) w.attribute("m", std::to_string(u.m));
      if (u.s) w.attribute("s", std::to_string(u.s));
      w.end();
    }
    w.end();
  }
  w.end();

  w.start("TypeDefinitions");
  for (const EnumerationType& e : enumerationTypes()) {
    w.start("EnumerationType");
    w.attribute("name", e.name);
    w.attribute("description", e.description);
    for (const EnumerationItem& item : e.items) {
      w.start("Item");
      w.attribute("name", item.name);
      w.attribute("value", std::to_string(item.value));
      w.attribute("description", item.description);
      w.end();
    }
    w.end();
  }
  w.end();

  w.start("LogCategories");
  for (const LogCategoryInfo& c : kLogCategories) {
    w.start("Category");
    w.attribute("name", c.name);
    w.attribute("description", c.description);
    w.end();
  }
  w.end();

  w.start("DefaultExperiment");
  w.attribute("startTime", number(kDefaultExperiment.startTime));
  w.attribute("stopTime", number(kDefaultExperiment.stopTime));
  w.attribute("stepSize", number(kDefaultExperiment.stepSize));
  w.end();

  w.start("ModelVariables");
  for (const Variable& v : variables()) writeVariable(w, v);
  w.end();

  // Outputs depend on the inputs the table names (the scene's solve or integration at their values);
  // initial unknowns are the outputs and calculated parameters (FMI 3.0.2 Sec. 2.4.8).
  w.start("ModelStructure");
  for (const Variable& v : variables())
    if (v.causality == Causality::Output) {
      w.start("Output");
      w.attribute("valueReference", std::to_string(v.vr));
      if (v.dependencies) {  // unset: the attribute is omitted (the output depends on every known)
        std::string refs, kinds;
        for (fmi3ValueReference d : *v.dependencies) {
          refs.append(refs.empty() ? "" : " ").append(std::to_string(d));
          kinds += kinds.empty() ? "dependent" : " dependent";
        }
        w.attribute("dependencies", refs);
        w.attribute("dependenciesKind", kinds);
      }
      w.end();
    }
  for (const Variable& v : variables())
    if (v.causality == Causality::Output || v.causality == Causality::CalculatedParameter) {
      w.start("InitialUnknown");
      w.attribute("valueReference", std::to_string(v.vr));
      w.end();
    }
  w.end();

  w.end();
  w.finish();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s <modelDescription.xml>\n", argv[0]);
    return 2;
  }
  try {
    writeModelDescription(argv[1]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", argv[0], e.what());
    return 1;
  }
  return 0;
}
