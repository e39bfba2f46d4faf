#include "simulation.hpp"

#include "host_errors.hpp"

namespace peristep::host {

namespace {

bool isParameter(const Variable& v) {
  return v.causality == Causality::Parameter || v.causality == Causality::StructuralParameter ||
         v.causality == Causality::CalculatedParameter;
}

Attribute toAttribute(const Variable& v, const Values& values, const ModelDescription& md) {
  if (v.type == VarType::Enumeration) {
    Setting s{v, values};
    return {v.name, describeValues(s, md)};  // item names read better than their integers
  }
  return std::visit(
      [&](const auto& vec) -> Attribute {
        using T = typename std::decay_t<decltype(vec)>::value_type;
        if constexpr (std::is_same_v<T, bool>) return {v.name, std::vector<std::int64_t>(vec.begin(), vec.end())};
        else return {v.name, vec};
      },
      values);
}

}  // namespace

void setSceneParameters(FmuInstance& instance, const Scene& scene) {
  bool structural = false;
  for (const Setting& s : scene.parameters) structural |= s.variable.causality == Causality::StructuralParameter;
  if (structural) {
    instance.enterConfigurationMode();
    for (const Setting& s : scene.parameters)
      if (s.variable.causality == Causality::StructuralParameter) instance.set(s.variable, s.values);
    instance.exitConfigurationMode();
  }
  for (const Setting& s : scene.parameters)
    if (s.variable.causality != Causality::StructuralParameter) instance.set(s.variable, s.values);
}

Simulation::Simulation(const FmuLibrary& library, const ModelDescription& md, const Scene& scene,
                       const FmuInstance::Options& options)
    : md_(md), scene_(scene), instance_(library, md, options), schedule_(loadSchedule(scene.loading)) {
  setSceneParameters(instance_, scene);
  // The ramped input starts at `from`: a fracture scene solves at its inputs when initialized, and bonds
  // broken at the input's start value (loadFactor 1) would stay broken.
  if (scene.loading.input) instance_.set(*scene.loading.input, std::vector<double>{scene.loading.from});
  instance_.enterInitializationMode(scene.loading.startTime, scene.loading.stopTime);
  instance_.exitInitializationMode();

  for (const Variable& v : md.variables) {
    if (v.causality != Causality::Output || v.type != VarType::Float64) continue;
    if (v.isArray()) {
      fields_.push_back(&v);
      fieldSizes_.push_back(elementCount(instance_.shape(v)));
    } else {
      scalars_.push_back(&v);
      scalarRefs_.push_back(v.valueReference);
    }
  }
}

ResultLayout Simulation::layout() {
  ResultLayout out;
  const Variable* x = md_.find("x");
  const Variable* y = md_.find("y");
  if (!x || !y || instance_.shape(*x).size() != 2)
    throw RunError(md_.modelName + " has no point coordinates x[ny][nx], y[ny][nx] to write a grid from");
  const auto grid = instance_.shape(*x);
  out.ny = grid[0];
  out.nx = grid[1];

  for (const Variable& v : md_.variables) {
    if (!isParameter(v)) continue;
    const auto shape = instance_.shape(v);
    const Values values = instance_.get(v, elementCount(shape));
    ArrayInfo info{v.name, shape, v.unit, v.description};
    if (v.type == VarType::Float64 && out.onGrid(info)) {
      out.constantArrays.push_back(info);
      out.constantValues.push_back(std::get<std::vector<double>>(values));
    } else {
      out.parameterAttributes.push_back(toAttribute(v, values, md_));
    }
  }
  for (std::size_t i = 0; i < scalars_.size(); ++i)
    out.scalars.push_back({scalars_[i]->name, {}, scalars_[i]->unit, scalars_[i]->description});
  for (const Variable* f : fields_) out.fields.push_back({f->name, instance_.shape(*f), f->unit, f->description});
  if (scene_.loading.input) out.inputName = scene_.loading.input->name;

  const Loading& l = scene_.loading;
  out.fileAttributes = {
      {"modelName", md_.modelName},
      {"instantiationToken", md_.instantiationToken},
      {"fmiVersion", md_.fmiVersion},
      {"scene", scene_.source},
      {"loadingInput", out.inputName.empty() ? std::string("(none)") : out.inputName},
      {"loadingFromTo", std::vector<double>{l.from, l.to}},
      {"loadingSteps", std::vector<std::uint64_t>{l.steps}},
      {"startStopTime", std::vector<double>{l.startTime, l.stopTime}},
  };
  return out;
}

StepValues Simulation::step(const Increment& inc) {
  if (!mayContinue_) throw RunError("the component asked to terminate; no further step is allowed");
  if (scene_.loading.input) instance_.set(*scene_.loading.input, std::vector<double>{inc.input});
  mayContinue_ = instance_.doStep(inc.time, inc.stepSize);

  StepValues out;
  out.time = inc.time + inc.stepSize;
  out.input = inc.input;
  out.scalars = instance_.getFloat64(scalarRefs_, scalarRefs_.size());
  for (std::size_t i = 0; i < fields_.size(); ++i)
    out.fields.push_back(std::get<std::vector<double>>(instance_.get(*fields_[i], fieldSizes_[i])));
  return out;
}

double Simulation::readScalar(const std::string& name) {
  const Variable* v = md_.find(name);
  if (!v || v->type != VarType::Float64 || v->isArray())
    throw RunError(md_.modelName + " has no scalar Float64 variable " + name);
  return std::get<std::vector<double>>(instance_.get(*v, 1)).front();
}

std::int64_t Simulation::readInteger(const std::string& name) {
  const Variable* v = md_.find(name);
  const bool integer = v && (v->type == VarType::Int8 || v->type == VarType::Int16 || v->type == VarType::Int32 ||
                             v->type == VarType::Int64);
  if (!integer || v->isArray()) throw RunError(md_.modelName + " has no scalar integer variable " + name);
  return std::get<std::vector<std::int64_t>>(instance_.get(*v, 1)).front();
}

}  // namespace peristep::host
