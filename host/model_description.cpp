#include "model_description.hpp"

#include <libxml/parser.h>
#include <libxml/tree.h>

#include <charconv>
#include <fstream>
#include <memory>
#include <sstream>
#include <utility>

#include "host_errors.hpp"

namespace peristep::host {

namespace {

constexpr std::pair<std::string_view, VarType> kTypeNames[] = {
    {"Float32", VarType::Float32}, {"Float64", VarType::Float64}, {"Int8", VarType::Int8},
    {"UInt8", VarType::UInt8},     {"Int16", VarType::Int16},     {"UInt16", VarType::UInt16},
    {"Int32", VarType::Int32},     {"UInt32", VarType::UInt32},   {"Int64", VarType::Int64},
    {"UInt64", VarType::UInt64},   {"Boolean", VarType::Boolean}, {"String", VarType::String},
    {"Binary", VarType::Binary},   {"Enumeration", VarType::Enumeration}, {"Clock", VarType::Clock},
};

constexpr std::pair<std::string_view, Causality> kCausalities[] = {
    {"parameter", Causality::Parameter},
    {"calculatedParameter", Causality::CalculatedParameter},
    {"structuralParameter", Causality::StructuralParameter},
    {"input", Causality::Input},
    {"output", Causality::Output},
    {"local", Causality::Local},
    {"independent", Causality::Independent},
};

constexpr std::pair<std::string_view, Variability> kVariabilities[] = {
    {"constant", Variability::Constant}, {"fixed", Variability::Fixed},
    {"tunable", Variability::Tunable},   {"discrete", Variability::Discrete},
    {"continuous", Variability::Continuous},
};

template <class Enum, std::size_t N>
std::string_view nameOf(const std::pair<std::string_view, Enum> (&table)[N], Enum value) {
  for (const auto& [name, v] : table)
    if (v == value) return name;
  return "?";
}

struct XmlDocDeleter {
  void operator()(xmlDoc* d) const { xmlFreeDoc(d); }
};

class Reader {
 public:
  explicit Reader(std::string source) : source_(std::move(source)) {}

  [[noreturn]] void fail(const xmlNode* node, const std::string& what) const {
    std::string where = source_;
    if (node) where += ":" + std::to_string(xmlGetLineNo(node));
    throw InputError(where + ": " + what);
  }

  static std::string_view name(const xmlNode* n) { return reinterpret_cast<const char*>(n->name); }

  static std::optional<std::string> attribute(const xmlNode* n, const char* key) {
    xmlChar* v = xmlGetProp(n, reinterpret_cast<const xmlChar*>(key));
    if (!v) return std::nullopt;
    std::string s(reinterpret_cast<const char*>(v));
    xmlFree(v);
    return s;
  }

  std::string required(const xmlNode* n, const char* key) const {
    auto v = attribute(n, key);
    if (!v) fail(n, std::string("<").append(name(n)).append("> lacks the attribute ").append(key));
    return *v;
  }

  template <class T>
  T number(const xmlNode* n, const char* key, const std::string& text) const {
    T value{};
    const char* end = text.data() + text.size();
    auto [ptr, ec] = std::from_chars(text.data(), end, value);
    if (ec != std::errc() || ptr != end)
      fail(n, "attribute " + std::string(key) + "=\"" + text + "\" is not a valid number");
    return value;
  }

  template <class T>
  std::optional<T> optionalNumber(const xmlNode* n, const char* key) const {
    auto v = attribute(n, key);
    if (!v) return std::nullopt;
    return number<T>(n, key, *v);
  }

  template <class Enum, std::size_t N>
  Enum keyword(const xmlNode* n, const char* key, const std::pair<std::string_view, Enum> (&table)[N],
               Enum fallback) const {
    auto v = attribute(n, key);
    if (!v) return fallback;
    for (const auto& [word, value] : table)
      if (word == *v) return value;
    fail(n, "unknown " + std::string(key) + " \"" + *v + "\"");
  }

 private:
  std::string source_;
};

std::vector<const xmlNode*> children(const xmlNode* parent, std::string_view tag = {}) {
  std::vector<const xmlNode*> out;
  for (const xmlNode* c = parent->children; c; c = c->next)
    if (c->type == XML_ELEMENT_NODE && (tag.empty() || Reader::name(c) == tag)) out.push_back(c);
  return out;
}

const xmlNode* child(const xmlNode* parent, std::string_view tag) {
  auto all = children(parent, tag);
  return all.empty() ? nullptr : all.front();
}

void readTypeDefinitions(const Reader& r, const xmlNode* defs, ModelDescription& md,
                         std::vector<std::pair<std::string, std::string>>& typeUnits) {
  for (const xmlNode* t : children(defs)) {
    if (Reader::name(t) == "EnumerationType") {
      EnumerationType e{r.required(t, "name"), {}};
      for (const xmlNode* item : children(t, "Item")) {
        const std::string value = r.required(item, "value");
        e.items.push_back({r.required(item, "name"), r.number<std::int64_t>(item, "value", value),
                           Reader::attribute(item, "description").value_or("")});
      }
      md.enumerations.push_back(std::move(e));
    } else if (auto unit = Reader::attribute(t, "unit")) {
      typeUnits.emplace_back(r.required(t, "name"), *unit);
    }
  }
}

Variable readVariable(const Reader& r, const xmlNode* v,
                      const std::vector<std::pair<std::string, std::string>>& typeUnits) {
  Variable var;
  const std::string_view tag = Reader::name(v);
  bool known = false;
  for (const auto& [typeName, type] : kTypeNames)
    if (typeName == tag) var.type = type, known = true;
  if (!known) r.fail(v, "unknown variable element <" + std::string(tag) + ">");

  var.name = r.required(v, "name");
  var.valueReference = r.number<std::uint32_t>(v, "valueReference", r.required(v, "valueReference"));
  var.causality = r.keyword(v, "causality", kCausalities, Causality::Local);
  // FMI 3.0: only Float32/Float64 default to continuous; every other type defaults to discrete.
  const bool isFloat = var.type == VarType::Float32 || var.type == VarType::Float64;
  var.variability = r.keyword(v, "variability", kVariabilities, isFloat ? Variability::Continuous : Variability::Discrete);
  var.initial = Reader::attribute(v, "initial").value_or("");
  var.declaredType = Reader::attribute(v, "declaredType").value_or("");
  var.description = Reader::attribute(v, "description").value_or("");
  var.unit = Reader::attribute(v, "unit").value_or("");
  if (var.unit.empty())
    for (const auto& [typeName, unit] : typeUnits)
      if (typeName == var.declaredType) var.unit = unit;
  var.start = Reader::attribute(v, "start");
  if (!var.start) {
    // String and Binary carry their start values as <Start value=".."/> children.
    std::string joined;
    for (const xmlNode* s : children(v, "Start")) {
      if (!joined.empty()) joined += ' ';
      joined += r.required(s, "value");
    }
    if (!joined.empty()) var.start = joined;
  }
  for (const xmlNode* d : children(v, "Dimension")) {
    Dimension dim{r.optionalNumber<std::uint64_t>(d, "start"), r.optionalNumber<std::uint32_t>(d, "valueReference")};
    if (dim.start.has_value() == dim.valueReference.has_value())
      r.fail(d, "<Dimension> of " + var.name + " needs exactly one of start and valueReference");
    var.dimensions.push_back(dim);
  }
  return var;
}

void checkConsistency(const Reader& r, const xmlNode* root, const ModelDescription& md) {
  for (const Variable& v : md.variables) {
    for (const Dimension& d : v.dimensions) {
      if (!d.valueReference) continue;
      const Variable* ref = md.findByValueReference(*d.valueReference);
      if (!ref || ref->causality != Causality::StructuralParameter)
        r.fail(root, "dimension of " + v.name + " refers to value reference " + std::to_string(*d.valueReference) +
                         ", which is no structural parameter");
    }
    if (v.type == VarType::Enumeration && !md.enumeration(v.declaredType))
      r.fail(root, "enumeration " + v.name + " has unknown declaredType \"" + v.declaredType + "\"");
  }
  for (std::size_t i = 0; i < md.variables.size(); ++i)
    for (std::size_t j = 0; j < i; ++j) {
      if (md.variables[i].name == md.variables[j].name)
        r.fail(root, "variable name " + md.variables[i].name + " is declared twice");
      if (md.variables[i].valueReference == md.variables[j].valueReference)
        r.fail(root, "value reference " + std::to_string(md.variables[i].valueReference) + " is used by both " +
                         md.variables[j].name + " and " + md.variables[i].name);
    }
}

}  // namespace

std::string_view toString(VarType t) { return nameOf(kTypeNames, t); }
std::string_view toString(Causality c) { return nameOf(kCausalities, c); }
std::string_view toString(Variability v) { return nameOf(kVariabilities, v); }

const EnumerationItem* EnumerationType::itemNamed(std::string_view item) const {
  for (const auto& i : items)
    if (i.name == item) return &i;
  return nullptr;
}

const EnumerationItem* EnumerationType::itemValued(std::int64_t value) const {
  for (const auto& i : items)
    if (i.value == value) return &i;
  return nullptr;
}

const Variable* ModelDescription::find(std::string_view name) const {
  for (const auto& v : variables)
    if (v.name == name) return &v;
  return nullptr;
}

const Variable* ModelDescription::findByValueReference(std::uint32_t vr) const {
  for (const auto& v : variables)
    if (v.valueReference == vr) return &v;
  return nullptr;
}

const EnumerationType* ModelDescription::enumeration(std::string_view typeName) const {
  for (const auto& e : enumerations)
    if (e.name == typeName) return &e;
  return nullptr;
}

ModelDescription parseModelDescription(std::string_view xml, const std::string& sourceName) {
  const Reader r(sourceName);
  // XML_PARSE_NONET: a model description never needs the network; errors are reported by us, once.
  std::unique_ptr<xmlDoc, XmlDocDeleter> doc(
      xmlReadMemory(xml.data(), static_cast<int>(xml.size()), sourceName.c_str(), nullptr,
                    XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING));
  if (!doc) {
    const xmlError* e = xmlGetLastError();
    std::string what = e && e->message ? e->message : "unknown error";
    while (!what.empty() && what.back() == '\n') what.pop_back();
    throw InputError(sourceName + (e ? ":" + std::to_string(e->line) : "") + ": not well-formed XML: " + what);
  }
  const xmlNode* root = xmlDocGetRootElement(doc.get());
  if (!root || Reader::name(root) != "fmiModelDescription") r.fail(root, "root element is not <fmiModelDescription>");

  ModelDescription md;
  md.fmiVersion = r.required(root, "fmiVersion");
  if (!md.fmiVersion.starts_with("3.")) r.fail(root, "fmiVersion is \"" + md.fmiVersion + "\", expected 3.x");
  md.modelName = r.required(root, "modelName");
  md.instantiationToken = r.required(root, "instantiationToken");
  md.description = Reader::attribute(root, "description").value_or("");
  md.generationTool = Reader::attribute(root, "generationTool").value_or("");
  if (const xmlNode* cs = child(root, "CoSimulation")) md.coSimulationIdentifier = r.required(cs, "modelIdentifier");

  std::vector<std::pair<std::string, std::string>> typeUnits;
  if (const xmlNode* defs = child(root, "TypeDefinitions")) readTypeDefinitions(r, defs, md, typeUnits);
  if (const xmlNode* cats = child(root, "LogCategories"))
    for (const xmlNode* c : children(cats, "Category")) md.logCategories.push_back(r.required(c, "name"));
  if (const xmlNode* ex = child(root, "DefaultExperiment")) {
    md.defaultExperiment.startTime = r.optionalNumber<double>(ex, "startTime");
    md.defaultExperiment.stopTime = r.optionalNumber<double>(ex, "stopTime");
    md.defaultExperiment.tolerance = r.optionalNumber<double>(ex, "tolerance");
    md.defaultExperiment.stepSize = r.optionalNumber<double>(ex, "stepSize");
  }
  const xmlNode* vars = child(root, "ModelVariables");
  if (!vars) r.fail(root, "no <ModelVariables>");
  for (const xmlNode* v : children(vars)) md.variables.push_back(readVariable(r, v, typeUnits));
  checkConsistency(r, root, md);
  return md;
}

ModelDescription readModelDescription(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string() + ": cannot open the model description");
  std::ostringstream text;
  text << in.rdbuf();
  return parseModelDescription(text.str(), file.string());
}

}  // namespace peristep::host
