#include "scene_file.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "host_errors.hpp"
#include "name_suggestion.hpp"
#include "scene_overrides.hpp"

namespace peristep::host {

namespace {

std::string_view kindOf(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a floating-point number";
    case toml::node_type::boolean: return "a boolean";
    case toml::node_type::array: return "an array";
    case toml::node_type::table: return "a table";
    default: return "a date or time";
  }
}

// Where a problem is: "file:line: [table] key".
class Context {
 public:
  Context(std::string source, const ModelDescription& md) : source_(std::move(source)), md_(md) {}

  [[noreturn]] void fail(const toml::source_region& at, std::string_view table, std::string_view key,
                         const std::string& problem) const {
    std::string where = source_;
    if (at.begin.line > 0) where += ":" + std::to_string(at.begin.line);
    where += ": [" + std::string(table) + "]";
    if (!key.empty()) where += " " + std::string(key);
    throw InputError(where + ": " + problem);
  }

  std::string suggestion(std::string_view name) const { return didYouMean(name, md_); }

  const ModelDescription& md() const { return md_; }
  const std::string& source() const { return source_; }

 private:
  std::string source_;
  const ModelDescription& md_;
};

void rejectUnknownKeys(const Context& c, const toml::table& t, std::string_view table,
                       std::initializer_list<std::string_view> allowed) {
  for (auto&& [key, node] : t)
    if (std::find(allowed.begin(), allowed.end(), key.str()) == allowed.end()) {
      std::string list;
      for (std::string_view a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
      c.fail(key.source(), table, key.str(), "unknown key (expected one of: " + list + ")");
    }
}

// Integer limits of each FMI integer type, for range checks of scene values.
struct IntRange {
  long double lo, hi;
};

IntRange rangeOf(VarType t) {
  switch (t) {
    case VarType::Int8: return {INT8_MIN, INT8_MAX};
    case VarType::UInt8: return {0, UINT8_MAX};
    case VarType::Int16: return {INT16_MIN, INT16_MAX};
    case VarType::UInt16: return {0, UINT16_MAX};
    case VarType::Int32: return {INT32_MIN, INT32_MAX};
    case VarType::UInt32: return {0, UINT32_MAX};
    case VarType::UInt64: return {0, static_cast<long double>(UINT64_MAX)};
    default: return {static_cast<long double>(INT64_MIN), static_cast<long double>(INT64_MAX)};
  }
}

bool isFloat(VarType t) { return t == VarType::Float32 || t == VarType::Float64; }
bool isUnsigned(VarType t) {
  return t == VarType::UInt8 || t == VarType::UInt16 || t == VarType::UInt32 || t == VarType::UInt64;
}
bool isSigned(VarType t) {
  return t == VarType::Int8 || t == VarType::Int16 || t == VarType::Int32 || t == VarType::Int64;
}

std::string itemList(const EnumerationType& e) {
  std::string list;
  for (const auto& i : e.items) list += (list.empty() ? "" : ", ") + i.name;
  return list;
}

// Reads the elements of one [parameters] entry (a scalar is an array of one) into typed values.
Values readElements(const Context& c, const Variable& var, const std::vector<const toml::node*>& elements) {
  const auto bad = [&](const toml::node& n, const std::string& expected) {
    c.fail(n.source(), "parameters", var.name,
           "expected " + expected + " for " + std::string(toString(var.type)) + ", got " + std::string(kindOf(n)));
  };
  if (isFloat(var.type)) {
    std::vector<double> out;
    for (const toml::node* n : elements) {
      if (!n->is_number()) bad(*n, "a number");
      out.push_back(n->value<double>().value());
    }
    return out;
  }
  if (var.type == VarType::Boolean) {
    std::vector<bool> out;
    for (const toml::node* n : elements) {
      if (!n->is_boolean()) bad(*n, "true or false");
      out.push_back(n->value<bool>().value());
    }
    return out;
  }
  if (var.type == VarType::Enumeration) {
    const EnumerationType& e = *c.md().enumeration(var.declaredType);
    std::vector<std::int64_t> out;
    for (const toml::node* n : elements) {
      if (!n->is_string()) bad(*n, "an item name (one of: " + itemList(e) + ")");
      const std::string item = n->value<std::string>().value();
      const EnumerationItem* found = e.itemNamed(item);
      if (!found)
        c.fail(n->source(), "parameters", var.name,
               "unknown item \"" + item + "\" of " + e.name + " (expected one of: " + itemList(e) + ")");
      out.push_back(found->value);
    }
    return out;
  }
  if (isSigned(var.type) || isUnsigned(var.type)) {
    const IntRange range = rangeOf(var.type);
    std::vector<std::int64_t> signedOut;
    std::vector<std::uint64_t> unsignedOut;
    for (const toml::node* n : elements) {
      if (!n->is_integer()) bad(*n, isUnsigned(var.type) ? "a non-negative integer" : "an integer");
      const std::int64_t v = n->value<std::int64_t>().value();
      if (v < range.lo || v > range.hi)
        c.fail(n->source(), "parameters", var.name,
               std::to_string(v) + " is out of range for " + std::string(toString(var.type)));
      if (isUnsigned(var.type)) unsignedOut.push_back(static_cast<std::uint64_t>(v));
      else signedOut.push_back(v);
    }
    if (isUnsigned(var.type)) return unsignedOut;
    return signedOut;
  }
  c.fail(elements.front()->source(), "parameters", var.name,
         "variables of type " + std::string(toString(var.type)) + " cannot be set from a scene file");
}

Setting readParameter(const Context& c, const toml::key& key, const toml::node& node) {
  const Variable* var = c.md().find(key.str());
  if (!var)
    c.fail(key.source(), "parameters", key.str(),
           "unknown variable: " + c.md().modelName + "'s model description has no variable of that name" +
               c.suggestion(key.str()));
  const bool settable = var->causality == Causality::Parameter ||
                        var->causality == Causality::StructuralParameter || var->causality == Causality::Input;
  if (!settable || var->variability == Variability::Constant)
    c.fail(key.source(), "parameters", key.str(),
           "is a " + std::string(toString(var->variability)) + " " + std::string(toString(var->causality)) +
               " and cannot be set");

  std::vector<const toml::node*> elements;
  if (const toml::array* a = node.as_array()) {
    if (!var->isArray())
      c.fail(node.source(), "parameters", var->name, "is a scalar " + std::string(toString(var->type)) +
                                                         ", got an array");
    for (const toml::node& e : *a) elements.push_back(&e);
    if (elements.empty()) c.fail(node.source(), "parameters", var->name, "empty array");
  } else {
    if (var->isArray())
      c.fail(node.source(), "parameters", var->name,
             "is an array variable: write it as an array, e.g. " + var->name + " = [...], got " +
                 std::string(kindOf(node)));
    elements.push_back(&node);
  }
  return {*var, readElements(c, *var, elements)};
}

std::optional<std::uint64_t> structuralValue(const Scene& scene, const Variable& structural) {
  if (const Setting* s = scene.setting(structural.name))
    if (const auto* v = std::get_if<std::vector<std::uint64_t>>(&s->values)) return v->front();
  if (structural.start) {
    std::uint64_t v = 0;
    std::istringstream in(*structural.start);
    if (in >> v) return v;
  }
  return std::nullopt;
}

// Checks the length of every array against its dimensions; a single dimension that refers to a
// structural parameter the scene leaves unset is set from the array's length (xi = [a, b] implies
// nModes = 2), so a scene need not repeat what its arrays already say.
void resolveDimensions(const Context& c, const toml::table& params, Scene& scene) {
  for (std::size_t i = 0; i < scene.parameters.size(); ++i) {
    const Setting s = scene.parameters[i];
    if (!s.variable.isArray()) continue;
    const auto at = params[s.variable.name].node()->source();
    const std::size_t given = valueCount(s.values);
    const auto& dims = s.variable.dimensions;
    if (dims.size() == 1 && dims[0].valueReference) {
      const Variable& structural = *c.md().findByValueReference(*dims[0].valueReference);
      if (!scene.setting(structural.name)) {
        scene.parameters.push_back({structural, std::vector<std::uint64_t>{given}});
        continue;
      }
    }
    std::uint64_t expected = 1;
    std::string shape;
    for (const Dimension& d : dims) {
      std::optional<std::uint64_t> extent = d.start;
      std::string label = d.start ? std::to_string(*d.start) : "";
      if (d.valueReference) {
        const Variable& structural = *c.md().findByValueReference(*d.valueReference);
        extent = structuralValue(scene, structural);
        label = structural.name;
        if (!extent) c.fail(at, "parameters", s.variable.name, "set " + structural.name + " too: it sizes this array");
        label += " = " + std::to_string(*extent);
      }
      expected *= *extent;
      shape += "[" + label + "]";
    }
    if (given != expected)
      c.fail(at, "parameters", s.variable.name,
             "has " + std::to_string(given) + " values but its shape " + shape + " needs " + std::to_string(expected));
  }
}

double number(const Context& c, const toml::table& t, std::string_view table, std::string_view key, double fallback) {
  const toml::node* n = t.get(key);
  if (!n) return fallback;
  if (!n->is_number()) c.fail(n->source(), table, key, "expected a number, got " + std::string(kindOf(*n)));
  const double v = n->value<double>().value();
  if (!std::isfinite(v)) c.fail(n->source(), table, key, "must be finite");
  return v;
}

std::string text(const Context& c, const toml::table& t, std::string_view table, std::string_view key) {
  const toml::node* n = t.get(key);
  if (!n) return {};
  if (!n->is_string()) c.fail(n->source(), table, key, "expected a string, got " + std::string(kindOf(*n)));
  std::string v = n->value<std::string>().value();
  if (v.empty()) c.fail(n->source(), table, key, "must not be empty");
  return v;
}

void readLoading(const Context& c, const toml::table* t, Scene& scene) {
  const DefaultExperiment& ex = c.md().defaultExperiment;
  Loading& l = scene.loading;
  l.startTime = ex.startTime.value_or(0.0);
  l.stopTime = ex.stopTime.value_or(1.0);
  const double stepSize = ex.stepSize.value_or(l.stopTime - l.startTime);
  if (stepSize > 0) l.steps = std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::llround((l.stopTime - l.startTime) / stepSize)));
  if (!t) return;

  rejectUnknownKeys(c, *t, "loading", {"input", "from", "to", "steps", "startTime", "stopTime"});
  if (const std::string name = text(c, *t, "loading", "input"); !name.empty()) {
    const Variable* v = c.md().find(name);
    const auto at = t->get("input")->source();
    if (!v) c.fail(at, "loading", "input", "unknown variable \"" + name + "\"" + c.suggestion(name));
    if (v->causality != Causality::Input || !isFloat(v->type) || v->isArray())
      c.fail(at, "loading", "input", name + " is not a scalar floating-point input");
    for (const char* key : {"from", "to"})
      if (!t->get(key)) c.fail(at, "loading", key, "missing: a ramped input needs from and to");
    l.input = *v;
    l.from = number(c, *t, "loading", "from", 0);
    l.to = number(c, *t, "loading", "to", 0);
  } else {
    for (const char* key : {"from", "to"})
      if (const toml::node* n = t->get(key)) c.fail(n->source(), "loading", key, "needs input = \"<input variable>\"");
  }
  if (const toml::node* n = t->get("steps")) {
    if (!n->is_integer() || n->value<std::int64_t>().value() < 1)
      c.fail(n->source(), "loading", "steps", "expected a positive integer");
    l.steps = static_cast<std::uint64_t>(n->value<std::int64_t>().value());
  }
  l.startTime = number(c, *t, "loading", "startTime", l.startTime);
  l.stopTime = number(c, *t, "loading", "stopTime", l.stopTime);
  if (!(l.stopTime > l.startTime))
    c.fail(t->source(), "loading", "stopTime", "must be greater than startTime (" + std::to_string(l.startTime) + ")");
}

void readLevels(const Context& c, const toml::table& t, Scene& scene) {
  rejectUnknownKeys(c, t, "convergence", {"levels"});
  const toml::node* n = t.get("levels");
  if (!n) c.fail(t.source(), "convergence", "levels", "missing (e.g. levels = [8, 16, 32, 64])");
  const toml::array* a = n->as_array();
  if (!a || a->empty()) c.fail(n->source(), "convergence", "levels", "expected a non-empty array of integers");
  for (const toml::node& e : *a) {
    if (!e.is_integer() || e.value<std::int64_t>().value() < 1)
      c.fail(e.source(), "convergence", "levels", "expected positive integers, got " + std::string(kindOf(e)));
    const auto level = static_cast<std::uint64_t>(e.value<std::int64_t>().value());
    if (!scene.levels.empty() && level <= scene.levels.back())
      c.fail(e.source(), "convergence", "levels", "must increase strictly");
    scene.levels.push_back(level);
  }
}

// [output] results: the scalar outputs a study is about (their distribution is drawn).
void readResults(const Context& c, const toml::table& t, Scene& scene) {
  const toml::node* n = t.get("results");
  if (!n) return;
  const toml::array* a = n->as_array();
  if (!a) c.fail(n->source(), "output", "results", "expected an array of output names, got " + std::string(kindOf(*n)));
  for (const toml::node& e : *a) {
    const std::string name = e.value<std::string>().value_or("");
    const Variable* v = c.md().find(name);
    if (!v || v->causality != Causality::Output || v->type != VarType::Float64 || v->isArray())
      c.fail(e.source(), "output", "results", "\"" + name + "\" is not a scalar Float64 output" + c.suggestion(name));
    scene.results.push_back(name);
  }
}

}  // namespace

const Setting* Scene::setting(std::string_view name) const {
  for (const Setting& s : parameters)
    if (s.variable.name == name) return &s;
  return nullptr;
}

const Variable& gridVariable(const ModelDescription& md, const char* name, const std::string& purpose) {
  const Variable* v = md.find(name);
  if (!v || v->causality != Causality::StructuralParameter || v->type != VarType::UInt64)
    throw InputError(md.modelName + " has no structural UInt64 parameter " + name + " to " + purpose);
  return *v;
}

Scene sceneWithGrid(const Scene& scene, const ModelDescription& md, std::uint64_t nx, std::uint64_t ny,
                    const std::string& purpose) {
  Scene out = scene;
  for (const auto& [name, n] : {std::pair{"nx", nx}, std::pair{"ny", ny}}) {
    const Variable& v = gridVariable(md, name, purpose);
    std::erase_if(out.parameters, [&](const Setting& s) { return s.variable.name == name; });
    out.parameters.push_back({v, std::vector<std::uint64_t>{n}});
  }
  return out;
}

Scene parseScene(std::string_view tomlText, const std::string& source, const ModelDescription& md,
                 const std::vector<ParameterOverride>& overrides) {
  const Context c(source, md);
  toml::table root;
  try {
    root = toml::parse(tomlText, source);
  } catch (const toml::parse_error& e) {
    throw InputError(source + ":" + std::to_string(e.source().begin.line) + ": TOML syntax error: " +
                     std::string(e.description()));
  }
  for (auto&& [key, node] : root)
    if (!node.is_table())
      c.fail(key.source(), key.str(), "", "expected a table [" + std::string(key.str()) + "], got " +
                                              std::string(kindOf(node)));
  rejectUnknownKeys(c, root, "top level", {"parameters", "loading", "output", "convergence"});
  if (!overrides.empty()) {
    if (!root.contains("parameters")) root.insert("parameters", toml::table{});
    applyOverrides(*root["parameters"].as_table(), overrides, md);
  }

  Scene scene;
  scene.source = source;
  if (const toml::table* params = root["parameters"].as_table()) {
    for (auto&& [key, node] : *params) scene.parameters.push_back(readParameter(c, key, node));
    resolveDimensions(c, *params, scene);
  }
  readLoading(c, root["loading"].as_table(), scene);
  if (const toml::table* out = root["output"].as_table()) {
    rejectUnknownKeys(c, *out, "output", {"file", "csv", "results"});
    scene.outputFile = text(c, *out, "output", "file");
    scene.csvFile = text(c, *out, "output", "csv");
    readResults(c, *out, scene);
  }
  if (const toml::table* conv = root["convergence"].as_table()) readLevels(c, *conv, scene);
  return scene;
}

Scene readScene(const std::filesystem::path& file, const ModelDescription& md,
                const std::vector<ParameterOverride>& overrides) {
  // Only a regular file of bounded size: a directory, a device (/dev/zero) or a pipe would otherwise be
  // read as an empty scene or never end.
  std::error_code ec;
  const auto status = std::filesystem::status(file, ec);
  if (!std::filesystem::exists(status)) throw InputError(file.string() + ": cannot open the scene file");
  if (!std::filesystem::is_regular_file(status))
    throw InputError(file.string() + ": not a regular file (a scene is a TOML file)");
  const std::uintmax_t size = std::filesystem::file_size(file, ec);
  if (ec || size > kMaxSceneFileBytes)
    throw InputError(file.string() + ": " + (ec ? ec.message() : std::to_string(size) + " bytes, more than the " +
                                                                     std::to_string(kMaxSceneFileBytes >> 20) +
                                                                     " MiB a scene file may hold"));
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string() + ": cannot open the scene file");
  std::string text(static_cast<std::size_t>(size), '\0');
  in.read(text.data(), static_cast<std::streamsize>(size));
  text.resize(static_cast<std::size_t>(in.gcount()));
  return parseScene(text, file.string(), md, overrides);
}

std::string describeValues(const Setting& s, const ModelDescription& md) {
  const EnumerationType* e = s.variable.type == VarType::Enumeration ? md.enumeration(s.variable.declaredType) : nullptr;
  std::ostringstream out;
  out.precision(17);
  std::visit(
      [&](const auto& vec) {
        if (s.variable.isArray()) out << '[';
        for (std::size_t i = 0; i < vec.size(); ++i) {
          if (i) out << ", ";
          using T = std::decay_t<decltype(vec[i])>;
          if constexpr (std::is_same_v<T, std::int64_t>) {
            const EnumerationItem* item = e ? e->itemValued(vec[i]) : nullptr;
            if (item) out << item->name;
            else out << vec[i];
          } else if constexpr (std::is_same_v<T, bool>) {
            out << (vec[i] ? "true" : "false");
          } else {
            out << vec[i];
          }
        }
        if (s.variable.isArray()) out << ']';
      },
      s.values);
  return out.str();
}

}  // namespace peristep::host
