// The checker of modelDescription.xml against the rules of the FMI 3.0.2 standard's text that fmi3ModelDescription.xsd
// cannot express (the schema test is fmi_model_description_test.cpp). The checker reads only the XML, so
// it covers every variable the table gains. Sections cited are those of the standard's chapter 2.4 "FMI
// Description Schema" (fmi-standard docs/2_4_common_schema.adoc): 2.4.1 fmiModelDescription, 2.4.2
// capability flags, 2.4.3 physical units, 2.4.4 variable types, 2.4.5 log categories, 2.4.6 default
// experiment, 2.4.7.2 array variables and structural parameters, 2.4.7.4 variable attributes (causality,
// variability), 2.4.7.5 type specific properties (declaredType, unit, initial, start), 2.4.8 model
// structure. "PeriStep rule" marks a rule the project adds on top of the standard.
#include "fmi_conformance_checker.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <map>
#include <set>
#include <sstream>

#include "model_description_xml.hpp"

namespace {

std::vector<std::string> words(const std::string& list) {
  std::istringstream in(list);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

std::optional<long double> numberOf(const std::string& text) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  const long double x = std::strtold(text.c_str(), &end);
  if (end != text.c_str() + text.size()) return std::nullopt;
  return x;
}

// ---- The model description as the rules see it --------------------------------------------------------

bool isFloat(const std::string& type) { return type == "Float32" || type == "Float64"; }
bool isNumeric(const std::string& type) {
  return isFloat(type) || type.find("Int") != std::string::npos;  // Int8..Int64, UInt8..UInt64
}

struct Dimension {
  std::optional<std::string> start, valueReference;
};

struct Variable {
  xmlNodePtr node = nullptr;
  std::string type, name, causality, variability;
  std::optional<std::string> valueReference, initial, start, declaredType, unit, displayUnit, min, max, derivative;
  std::vector<Dimension> dimensions;
  std::size_t position = 0;  // index in <ModelVariables>
};

Variable readVariable(xmlNodePtr node, std::size_t position) {
  Variable v;
  v.node = node;
  v.type = elementName(node);
  v.name = attribute(node, "name");
  v.valueReference = optionalAttribute(node, "valueReference");
  // Defaults: causality local (Sec. 2.4.7.4 causality); variability continuous for Float32/Float64 and
  // discrete otherwise (Sec. 2.4.7.4 variability).
  v.causality = attribute(node, "causality", "local");
  v.variability = attribute(node, "variability", isFloat(v.type) ? "continuous" : "discrete");
  v.initial = optionalAttribute(node, "initial");
  v.start = optionalAttribute(node, "start");
  if (!v.start && !children(node, "Start").empty()) v.start = "";  // String/Binary start elements
  v.declaredType = optionalAttribute(node, "declaredType");
  v.unit = optionalAttribute(node, "unit");
  v.displayUnit = optionalAttribute(node, "displayUnit");
  v.min = optionalAttribute(node, "min");
  v.max = optionalAttribute(node, "max");
  v.derivative = optionalAttribute(node, "derivative");
  for (xmlNodePtr d : children(node, "Dimension"))
    v.dimensions.push_back({optionalAttribute(d, "start"), optionalAttribute(d, "valueReference")});
  v.position = position;
  return v;
}

// Allowed combinations of variability and causality: table "Allowed combinations of
// variability/causality" (Sec. 2.4.7.4).
bool combinationAllowed(const std::string& variability, const std::string& causality) {
  static const std::map<std::string, std::set<std::string>> allowed{
      {"constant", {"output", "local"}},
      {"fixed", {"structuralParameter", "parameter", "calculatedParameter", "local"}},
      {"tunable", {"structuralParameter", "parameter", "calculatedParameter", "local"}},
      {"discrete", {"input", "output", "local"}},
      {"continuous", {"input", "output", "local", "independent"}},
  };
  const auto it = allowed.find(variability);
  return it != allowed.end() && it->second.count(causality) == 1;
}

// Table "Definition of initial" (Sec. 2.4.7.4): the allowed values, the default first; empty: initial
// must not be given.
std::vector<std::string> initialChoices(const std::string& variability, const std::string& causality) {
  if (causality == "independent") return {};
  if (variability == "constant") return {"exact"};
  if (causality == "structuralParameter" || causality == "parameter") return {"exact"};
  if (causality == "calculatedParameter") return {"calculated", "approx"};
  if (causality == "input") return {"exact"};
  if (causality == "output" || causality == "local") {
    if (variability == "fixed" || variability == "tunable") return {"calculated", "approx"};
    return {"calculated", "exact", "approx"};
  }
  return {};
}

// Quantities that are dimensionless by nature (ratios, counts, standardized coordinates, tolerances).
// PeriStep rule: every other floating point variable carries a unit, so an importer can check what it
// connects; a new unitless variable has to be added here, with its reason, or be given a unit.
const std::set<std::string> kDimensionless{
    "deltaOverH",           // horizon over grid spacing
    "poissonRatio",         //
    "materialPoissonRatio", // Poisson ratio per point
    "modulusContrast",      // ratio of two moduli
    "jitter",               // fraction of the grid spacing
    "xi",                   // standardized random coordinates
    "xiScale",              // scale of a standardized coordinate (the coordinates are dimensionless)
    "crystalFraction",      // area fraction
    "fieldStd",             // standard deviation of a dimensionless Gaussian field
    "loadFactor",           // scale of the loads
    "damage",               // broken-bond fraction or the indicator Z
    "retainedVariance",     // variance fraction
    "brokenBonds",          // a count
    "forceEvaluations",     // a count
    "integratorTolerance",  // relative tolerance
    "scatterDenominator",   // 002:(26): divides a relative perturbation
    "weibullShape",         // shape of a Weibull law
    "barStrain",            // a strain
    "collarDuxDx", "collarDuxDy", "collarDuyDx", "collarDuyDy",  // a displacement gradient (strain, rotation)
    "cyclicExponent",       // n', the exponent of a power law
    "learnedCriticalStretch",       // a stretch
    "predictionErrorDisplacement",  // relative error
    "predictionErrorDamage",        // relative error
    "strainXX", "strainYY", "strainXY",  // patchTest: a displacement gradient
    "patchError",                   // relative error
};

class Checker {
 public:
  explicit Checker(xmlNodePtr root) : root_(root) {
    std::size_t k = 0;
    for (xmlNodePtr node : children(firstChild(root, "ModelVariables"))) variables_.push_back(readVariable(node, k++));
    for (const Variable& v : variables_)
      if (v.valueReference) byReference_.emplace(*v.valueReference, &v);
    for (xmlNodePtr u : children(firstChild(root, "UnitDefinitions"), "Unit")) units_.emplace(attribute(u, "name"), u);
    for (xmlNodePtr t : children(firstChild(root, "TypeDefinitions"))) types_.emplace(attribute(t, "name"), t);
  }

  std::vector<std::string> run() {
    modelDescription();
    unitDefinitions();
    typeDefinitions();
    logCategories();
    defaultExperiment();
    for (const Variable& v : variables_) variable(v);
    uniqueness();
    arrays();
    modelStructure();
    return std::move(violations_);
  }

 private:
  void fail(const std::string& rule, const std::string& what) { violations_.push_back(rule + ": " + what); }
  static std::string who(const Variable& v) { return v.name + " (vr " + v.valueReference.value_or("?") + ")"; }
  const Variable* find(const std::string& vr) const {
    const auto it = byReference_.find(vr);
    return it == byReference_.end() ? nullptr : it->second;
  }

  void modelDescription() {
    // Sec. 2.4.1: fmiVersion is 3.0 for this standard; the instantiation token is passed to fmi3Instantiate*.
    if (attribute(root_, "fmiVersion").rfind("3.", 0) != 0) fail("fmiVersion (Sec. 2.4.1)", "not 3.x");
    // Sec. 2.4.2: modelIdentifier is a "short class name according to C syntax".
    for (const char* kind : {"ModelExchange", "CoSimulation", "ScheduledExecution"})
      if (xmlNodePtr e = firstChild(root_, kind)) {
        const std::string id = attribute(e, "modelIdentifier");
        bool ok = !id.empty() && !std::isdigit(static_cast<unsigned char>(id[0]));
        for (char c : id) ok = ok && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
        if (!ok) fail("modelIdentifier (Sec. 2.4.2)", "'" + id + "' is not a C identifier");
        // canSerializeFMUState requires canGetAndSetFMUState.
        if (attribute(e, "canSerializeFMUState") == "true" && attribute(e, "canGetAndSetFMUState") != "true")
          fail("canSerializeFMUState (Sec. 2.4.2)", "true without canGetAndSetFMUState");
      }
  }

  void unitDefinitions() {
    // Sec. 2.4.3: unit names unique; display unit names unique within their unit; inverse only with offset 0.
    std::set<std::string> names;
    for (xmlNodePtr u : children(firstChild(root_, "UnitDefinitions"), "Unit")) {
      const std::string name = attribute(u, "name");
      if (!names.insert(name).second) fail("unique unit names (Sec. 2.4.3)", name);
      std::set<std::string> display;
      for (xmlNodePtr d : children(u, "DisplayUnit")) {
        if (!display.insert(attribute(d, "name")).second)
          fail("unique display unit names (Sec. 2.4.3)", name + ": " + attribute(d, "name"));
        if (attribute(d, "inverse") == "true" && numberOf(attribute(d, "offset", "0")).value_or(1) != 0)
          fail("display unit inverse (Sec. 2.4.3)", name + ": inverse with an offset");
      }
    }
  }

  void unitReference(const std::string& owner, const std::optional<std::string>& unit,
                     const std::optional<std::string>& displayUnit) {
    // Sec. 2.4.4 / 2.4.7.5: unit references a <Unit>, "which must exist"; displayUnit a <DisplayUnit> of
    // that unit, and needs a unit.
    if (unit && !units_.count(*unit)) fail("unit defined in <UnitDefinitions> (Sec. 2.4.7.5)", owner + ": " + *unit);
    if (displayUnit) {
      bool found = false;
      if (unit && units_.count(*unit))
        for (xmlNodePtr d : children(units_.at(*unit), "DisplayUnit"))
          found = found || attribute(d, "name") == *displayUnit;
      if (!found) fail("displayUnit defined under its unit (Sec. 2.4.7.5)", owner + ": " + *displayUnit);
    }
  }

  void typeDefinitions() {
    // Sec. 2.4.4: type names unique and different from every variable name; enumeration items non-empty,
    // with unique names and values.
    std::set<std::string> names, variableNames;
    for (const Variable& v : variables_) variableNames.insert(v.name);
    for (xmlNodePtr t : children(firstChild(root_, "TypeDefinitions"))) {
      const std::string name = attribute(t, "name");
      if (!names.insert(name).second) fail("unique type names (Sec. 2.4.4)", name);
      if (variableNames.count(name)) fail("type name differs from variable names (Sec. 2.4.4)", name);
      unitReference("type " + name, optionalAttribute(t, "unit"), optionalAttribute(t, "displayUnit"));
      if (elementName(t) != "EnumerationType") continue;
      std::set<std::string> itemNames, itemValues;
      const auto items = children(t, "Item");
      if (items.empty()) fail("enumeration items (Sec. 2.4.4)", name + " has none");
      for (xmlNodePtr item : items) {
        if (!itemNames.insert(attribute(item, "name")).second)
          fail("unique enumeration item names (Sec. 2.4.4)", name + ": " + attribute(item, "name"));
        if (!itemValues.insert(attribute(item, "value")).second)
          fail("unique enumeration item values (Sec. 2.4.4)", name + ": " + attribute(item, "value"));
      }
    }
  }

  void logCategories() {
    std::set<std::string> names;  // Sec. 2.4.5: category names unique
    for (xmlNodePtr c : children(firstChild(root_, "LogCategories"), "Category"))
      if (!names.insert(attribute(c, "name")).second)
        fail("unique log category names (Sec. 2.4.5)", attribute(c, "name"));
  }

  void defaultExperiment() {
    // PeriStep rule (Sec. 2.4.6 gives the meaning, not the bounds): a usable default run.
    xmlNodePtr e = firstChild(root_, "DefaultExperiment");
    if (!e) return;
    const auto start = numberOf(attribute(e, "startTime", "0")), stop = numberOf(attribute(e, "stopTime", "1e300")),
               step = numberOf(attribute(e, "stepSize", "1"));
    if (!start || !stop || !(*start < *stop)) fail("default experiment (PeriStep rule)", "startTime >= stopTime");
    if (!step || !(*step > 0)) fail("default experiment (PeriStep rule)", "stepSize <= 0");
  }

  void variable(const Variable& v) {
    // Sec. 2.4.7.4 variability: "Only a variable of type Float32 or Float64 can be continuous".
    if (v.variability == "continuous" && !isFloat(v.type))
      fail("continuous only for Float32/Float64 (Sec. 2.4.7.4)", who(v) + " is " + v.type);
    if (!combinationAllowed(v.variability, v.causality))
      fail("variability/causality combination (Sec. 2.4.7.4, table of allowed combinations)",
           who(v) + ": " + v.variability + " " + v.causality);
    // Sec. 2.4.7.4 independent: exactly one, floating point, continuous, no start and no initial.
    if (v.causality == "independent" && !isFloat(v.type))
      fail("independent variable is floating point (Sec. 2.4.7.4)", who(v));

    // Table "Definition of initial" and the start rules of Sec. 2.4.7.5.
    const auto choices = initialChoices(v.variability, v.causality);
    if (v.initial && (choices.empty() || std::find(choices.begin(), choices.end(), *v.initial) == choices.end()))
      fail("initial allowed for causality/variability (Sec. 2.4.7.5, table Definition of initial)",
           who(v) + ": initial=" + *v.initial + " with " + v.variability + " " + v.causality);
    const std::string initial = v.initial.value_or(choices.empty() ? "" : choices.front());
    const bool needsStart = initial == "exact" || initial == "approx" || v.causality == "input" ||
                            v.causality == "parameter" || v.causality == "structuralParameter" ||
                            v.variability == "constant";
    const bool forbidsStart = initial == "calculated" || v.causality == "independent";
    if (needsStart && !v.start) fail("start value required (Sec. 2.4.7.5)", who(v));
    if (forbidsStart && v.start) fail("start value not allowed (Sec. 2.4.7.5)", who(v));

    // Sec. 2.4.7.4: structural parameters have no <Dimension>; intermediateUpdate not on parameters;
    // canHandleMultipleSetPerTimeInstant only on inputs.
    if (v.causality == "structuralParameter" && !v.dimensions.empty())
      fail("structural parameter without <Dimension> (Sec. 2.4.7.4)", who(v));
    if (v.causality == "parameter" && attribute(v.node, "intermediateUpdate") == "true")
      fail("intermediateUpdate not on parameters (Sec. 2.4.7.4)", who(v));
    if (optionalAttribute(v.node, "canHandleMultipleSetPerTimeInstant") && v.causality != "input")
      fail("canHandleMultipleSetPerTimeInstant only for inputs (Sec. 2.4.7.4)", who(v));

    // Sec. 2.4.7.5 declaredType: names a type of the variable's kind; required for <Enumeration>.
    xmlNodePtr type = nullptr;
    if (v.declaredType) {
      const auto it = types_.find(*v.declaredType);
      if (it == types_.end())
        fail("declaredType defined (Sec. 2.4.7.5)", who(v) + ": " + *v.declaredType);
      else if (elementName(it->second) != v.type + "Type")
        fail("declaredType of the variable's type (Sec. 2.4.7.5)", who(v) + ": " + elementName(it->second));
      else
        type = it->second;
    } else if (v.type == "Enumeration") {
      fail("Enumeration needs declaredType (Sec. 2.4.7.5)", who(v));
    }
    unitReference(who(v), v.unit, v.displayUnit);
    if (isFloat(v.type) && !v.unit && !(type && optionalAttribute(type, "unit")) && !kDimensionless.count(v.name))
      fail("unit for every physical quantity (PeriStep rule)",
           who(v) + " has no unit and is not listed as dimensionless");

    startWithinBounds(v, type);
  }

  // Sec. 2.4.4 min/max: the value lies in [min, max], the variable's bounds overriding its type's; for an
  // enumeration the start must also be one of its items. Each element of an array start list counts.
  void startWithinBounds(const Variable& v, xmlNodePtr type) {
    if (!isNumeric(v.type) && v.type != "Enumeration") return;
    const auto bound = [&](const std::optional<std::string>& own, const char* name) -> std::optional<long double> {
      if (own) return numberOf(*own);
      if (type && optionalAttribute(type, name)) return numberOf(*optionalAttribute(type, name));
      return std::nullopt;
    };
    const auto lo = bound(v.min, "min"), hi = bound(v.max, "max");
    if (lo && hi && *lo > *hi) fail("min <= max (Sec. 2.4.4)", who(v));
    std::set<std::string> items;
    if (v.type == "Enumeration" && type)
      for (xmlNodePtr item : children(type, "Item")) items.insert(attribute(item, "value"));
    if (!v.start) return;
    for (const std::string& s : words(*v.start)) {
      const auto x = numberOf(s);
      if (!x) {
        fail("start value of the variable's type", who(v) + ": '" + s + "'");
        continue;
      }
      if ((lo && *x < *lo) || (hi && *x > *hi)) fail("start within [min, max] (Sec. 2.4.4)", who(v) + ": start " + s);
      if (v.type == "Enumeration" && !items.count(s))
        fail("enumeration start is an item value (Sec. 2.4.4)", who(v) + ": start " + s);
    }
  }

  void uniqueness() {
    // Sec. 2.4.7.4: names unique and non-empty; valueReference unique for all variables.
    std::set<std::string> names, references;
    for (const Variable& v : variables_) {
      if (v.name.empty() || !names.insert(v.name).second) fail("unique, non-empty names (Sec. 2.4.7.4)", who(v));
      if (v.valueReference && !references.insert(*v.valueReference).second)
        fail("unique value references (Sec. 2.4.7.4)", who(v));
    }
    std::size_t independent = 0;
    for (const Variable& v : variables_) independent += v.causality == "independent";
    if (independent != 1) fail("exactly one independent variable (Sec. 2.4.7.4)", std::to_string(independent));
  }

  void arrays() {
    // Sec. 2.4.7.2 "Array variables and structural parameters".
    for (const Variable& v : variables_) {
      std::size_t elements = 1;
      for (const Dimension& d : v.dimensions) {
        if (d.start.has_value() == d.valueReference.has_value())
          fail("<Dimension> has either start or valueReference (Sec. 2.4.7.2)", who(v));
        std::optional<long double> size;
        if (d.start) size = numberOf(*d.start);
        if (d.valueReference) {
          const Variable* s = find(*d.valueReference);
          if (!s) {
            fail("<Dimension> references a variable (Sec. 2.4.7.2)", who(v) + ": vr " + *d.valueReference);
            continue;
          }
          // The referenced variable: UInt64, and a constant or a structural parameter, start > 0.
          if (s->type != "UInt64" || !(s->variability == "constant" || s->causality == "structuralParameter"))
            fail("<Dimension> references a UInt64 constant or structural parameter (Sec. 2.4.7.2)",
                 who(v) + " -> " + who(*s));
          // PeriStep rule: the size is declared before the array that uses it (readers resolve in one pass).
          if (s->position > v.position)
            fail("structural parameter declared before its array (PeriStep rule)", who(v) + " -> " + who(*s));
          if (s->start) size = numberOf(*s->start);
        }
        if (!size || !(*size > 0))
          fail("initial dimension sizes positive (Sec. 2.4.7.2)", who(v));
        else
          elements *= static_cast<std::size_t>(*size);
      }
      // Sec. 2.4.7.5 start: a single value, or one per element of the array.
      if (v.start && !v.dimensions.empty() && v.type != "String" && v.type != "Binary") {
        const std::size_t n = words(*v.start).size();
        if (n != 1 && n != elements)
          fail("start gives one value or one per element (Sec. 2.4.7.5)",
               who(v) + ": " + std::to_string(n) + " values for " + std::to_string(elements) + " elements");
      }
    }
  }

  // Sec. 2.4.8: the knowns an <Output> or <ContinuousStateDerivative> may depend on at a communication
  // point (inputs, continuous or discrete states, parameters, the independent variable), and those an
  // <InitialUnknown> may depend on (inputs, variables with initial exact, the independent variable).
  bool knownAtCommunicationPoint(const Variable& k) const {
    return k.causality == "input" || k.causality == "parameter" || k.causality == "independent" ||
           states_.count(*k.valueReference) == 1;
  }
  bool knownInInitialization(const Variable& k) const {
    if (k.causality == "input" || k.causality == "independent") return true;
    const auto choices = initialChoices(k.variability, k.causality);
    return k.initial.value_or(choices.empty() ? "" : choices.front()) == "exact";
  }

  void dependencies(xmlNodePtr element, const Variable& unknown, bool initialization) {
    const auto deps = optionalAttribute(element, "dependencies");
    const auto kinds = optionalAttribute(element, "dependenciesKind");
    if (kinds && !deps) fail("dependenciesKind needs dependencies (Sec. 2.4.8)", who(unknown));
    if (!deps) return;
    const auto refs = words(*deps);
    if (kinds && words(*kinds).size() != refs.size())
      fail("dependenciesKind as long as dependencies (Sec. 2.4.8)", who(unknown));
    std::set<std::string> seen;
    for (const std::string& r : refs) {
      const Variable* k = find(r);
      if (!k) {
        fail("dependencies name variables (Sec. 2.4.8)", who(unknown) + ": vr " + r);
        continue;
      }
      if (!seen.insert(r).second) fail("dependencies listed once", who(unknown) + ": vr " + r);
      if (!(initialization ? knownInInitialization(*k) : knownAtCommunicationPoint(*k)))
        fail("dependencies are knowns (Sec. 2.4.8)", who(unknown) + " on " + who(*k));
    }
    if (!kinds) return;
    for (const std::string& kind : words(*kinds)) {
      // Only "dependent" for non-float unknowns; InitialUnknown has no fixed/tunable/discrete kinds.
      if (kind != "dependent" && !isFloat(unknown.type))
        fail("dependenciesKind of a non-float unknown is dependent (Sec. 2.4.8)", who(unknown) + ": " + kind);
      if (initialization && kind != "dependent" && kind != "constant")
        fail("dependenciesKind of an InitialUnknown (Sec. 2.4.8)", who(unknown) + ": " + kind);
    }
  }

  void modelStructure() {
    xmlNodePtr structure = firstChild(root_, "ModelStructure");
    // Continuous-time states: the variables a <ContinuousStateDerivative>'s derivative attribute names.
    std::vector<const Variable*> derivatives;
    for (xmlNodePtr e : children(structure, "ContinuousStateDerivative")) {
      const Variable* d = find(attribute(e, "valueReference"));
      if (!d || !d->derivative || !isFloat(d->type) || d->variability != "continuous") {
        fail("<ContinuousStateDerivative> is a continuous float with derivative (Sec. 2.4.8)",
             attribute(e, "valueReference"));
        continue;
      }
      derivatives.push_back(d);
      states_.insert(*d->derivative);
      dependencies(e, *d, false);
    }
    // Every derivative of a continuous local or output state is listed (Sec. 2.4.8 ContinuousStateDerivative).
    for (const Variable& v : variables_)
      if (v.derivative && isFloat(v.type) && v.variability == "continuous" && v.causality != "input") {
        const Variable* s = find(*v.derivative);
        if (!s)
          fail("derivative references a variable (Sec. 2.4.7.5)", who(v));
        else if (s->causality != "input" && std::find(derivatives.begin(), derivatives.end(), &v) == derivatives.end())
          fail("every continuous-time state listed (Sec. 2.4.8 ContinuousStateDerivative)", who(v));
      }

    // <Output>: every output exactly once, nothing else; PeriStep rule: in the order of <ModelVariables>.
    std::vector<std::string> listed, expected;
    for (xmlNodePtr e : children(structure, "Output")) {
      listed.push_back(attribute(e, "valueReference"));
      const Variable* v = find(listed.back());
      if (!v || v->causality != "output")
        fail("<Output> lists outputs only (Sec. 2.4.8)", listed.back());
      else
        dependencies(e, *v, false);
    }
    for (const Variable& v : variables_)
      if (v.causality == "output") expected.push_back(v.valueReference.value_or(""));
    const std::set<std::string> listedSet(listed.begin(), listed.end()), expectedSet(expected.begin(), expected.end());
    if (listedSet.size() != listed.size()) fail("<Output> lists each output once (Sec. 2.4.8)", "duplicates");
    for (const std::string& vr : expected)
      if (!listedSet.count(vr)) fail("every output listed as <Output> (Sec. 2.4.8)", who(*find(vr)));
    if (listedSet == expectedSet && listed.size() == expected.size() && listed != expected)
      fail("<Output> in the order of <ModelVariables> (PeriStep rule)", "order differs");

    // <InitialUnknown>: exactly the outputs with initial approx or calculated, the calculated parameters
    // and the continuous states and derivatives with initial approx or calculated; no duplicates.
    std::set<std::string> initial, expectedInitial;
    for (xmlNodePtr e : children(structure, "InitialUnknown")) {
      const std::string vr = attribute(e, "valueReference");
      if (!initial.insert(vr).second) fail("<InitialUnknown> without duplicates (Sec. 2.4.8)", vr);
      if (const Variable* v = find(vr))
        dependencies(e, *v, true);
      else
        fail("<InitialUnknown> names a variable (Sec. 2.4.8)", vr);
    }
    for (const Variable& v : variables_) {
      const auto choices = initialChoices(v.variability, v.causality);
      const std::string init = v.initial.value_or(choices.empty() ? "" : choices.front());
      const bool computed = init == "approx" || init == "calculated";
      const bool stateOrDerivative = states_.count(v.valueReference.value_or("")) ||
                                     std::find(derivatives.begin(), derivatives.end(), &v) != derivatives.end();
      if ((v.causality == "output" && computed) || v.causality == "calculatedParameter" ||
          (stateOrDerivative && computed))
        expectedInitial.insert(v.valueReference.value_or(""));
    }
    for (const std::string& vr : expectedInitial)
      if (!initial.count(vr)) fail("every initial unknown listed (Sec. 2.4.8 InitialUnknown)", who(*find(vr)));
    for (const std::string& vr : initial)
      if (!expectedInitial.count(vr) && find(vr))
        fail("<InitialUnknown> lists initial unknowns only (Sec. 2.4.8)", who(*find(vr)));
  }

  xmlNodePtr root_;
  std::vector<Variable> variables_;
  std::map<std::string, const Variable*> byReference_;
  std::map<std::string, xmlNodePtr> units_, types_;
  std::set<std::string> states_;
  std::vector<std::string> violations_;
};

}  // namespace

std::vector<std::string> conformanceViolations(xmlNodePtr root) { return Checker(root).run(); }
