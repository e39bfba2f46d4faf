#include "fmi/model_binding.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "core/errors.hpp"
#include "core/memory.hpp"
#include "core/number_text.hpp"
#include "fmi/variables.hpp"
#include "peristep.h"
#include "scenes/enumeration_values.hpp"
#include "scenes/parameter_constants.hpp"
#include "scenes/scene_declaration.hpp"

namespace peristep::fmi {

namespace {

using P = const ParameterValues&;
using M = const SceneModel*;

// A field of the model copied into an importer's array; the sizes agree by construction.
void copyField(const std::vector<double>& field, std::span<double> out) {
  if (field.size() != out.size())
    throw SolverFailure("internal error: field of " + std::to_string(field.size()) + " values for " +
                        std::to_string(out.size()) + " elements");
  std::copy(field.begin(), field.end(), out.begin());
}

// An exact-moment field, or zeros where the scene has none (hasExactMoments tells which). The moments
// scale with the load: a load that overflows them is refused here, where they are read.
void exactMoment(M m, int which, std::span<double> out) {
  const std::vector<double> v = m->exactMoment(which);
  if (v.empty()) std::fill(out.begin(), out.end(), 0.0);
  else copyField(v, out);
  if (!std::all_of(out.begin(), out.end(), [](double x) { return std::isfinite(x); }))
    throw SolverFailure("the exact moments are not finite at loadFactor = " + numberText(m->loadFactor()) +
                        ": the load is too large for double precision");
}

// A held grip's reaction component (0: x, 1: y).
template <Side side, int component>
void gripReaction(P, M m, std::span<double> out) {
  out[0] = m->gripReaction(side)[component];
}

std::vector<double> copied(std::span<const double> v) { return {v.begin(), v.end()}; }

// A scene's own parameter in double precision (integers and enumeration values are exact below 2^53).
std::vector<double> asDoubles(const ParameterValues& v, const Variable& own) {
  const auto convert = [](auto values) { return std::vector<double>(values.begin(), values.end()); };
  switch (own.type) {
    case VarType::Float64: return convert(v.get<double>(own.vr));
    case VarType::Int32: return convert(v.get<std::int32_t>(own.vr));
    case VarType::UInt64: return convert(v.get<std::uint64_t>(own.vr));
    case VarType::Enumeration: return convert(v.get<std::int64_t>(own.vr));
  }
  return {};
}

// Every scene's own outputs, read through SceneModel::ownOutput (0 while another scene runs).
std::vector<ComputedVariable> ownOutputs() {
  std::vector<ComputedVariable> computed;
  for (const SceneDeclaration& scene : sceneDeclarations())
    for (const OwnOutput& o : scene.outputs)
      computed.push_back({o.vr, Needs::Solution,
                          [vr = o.vr](const ParameterValues&, const SceneModel* m, std::span<double> out) {
                            out[0] = m->ownOutput(vr);
                          }});
  return computed;
}

// A map of zeros is none: the scene then carries no array for it.
std::vector<double> nonZero(std::span<const double> v) {
  return std::all_of(v.begin(), v.end(), [](double x) { return x == 0; }) ? std::vector<double>{} : copied(v);
}

// The components a held grip or box prescribes (the enumeration's values are checked when they are set).
HeldComponents heldComponents(std::int64_t grip) {
  return grip == PERISTEP_GRIP_HELD_X ? HeldComponents::X
         : grip == PERISTEP_GRIP_HELD_Y ? HeldComponents::Y
                                        : HeldComponents::Both;
}

// Reaction of the grip boxes, one per entry of gripBoxHold: the model numbers the held ones only.
template <int component>
void boxReactions(P p, M m, std::span<double> out) {
  const auto hold = p.get<std::int64_t>(PERISTEP_VR_GRIP_BOX_HOLD);
  std::size_t held = 0;
  for (std::size_t b = 0; b < out.size(); ++b)
    out[b] = hold[b] == PERISTEP_GRIP_FREE ? 0.0 : m->boxReaction(held++)[component];
}

SpecimenSpec specimen(const ParameterValues& v) {
  SpecimenSpec s;
  s.youngsModulus = copied(v.get<double>(PERISTEP_VR_MATERIAL_YOUNGS_MODULUS));
  s.poissonRatio = copied(v.get<double>(PERISTEP_VR_MATERIAL_POISSON_RATIO));
  s.fractureEnergy = copied(v.get<double>(PERISTEP_VR_MATERIAL_FRACTURE_ENERGY));
  s.density = copied(v.get<double>(PERISTEP_VR_MATERIAL_DENSITY));
  const auto x0 = v.get<double>(PERISTEP_VR_CRACK_X0), y0 = v.get<double>(PERISTEP_VR_CRACK_Y0);
  const auto x1 = v.get<double>(PERISTEP_VR_CRACK_X1), y1 = v.get<double>(PERISTEP_VR_CRACK_Y1);
  for (std::size_t k = 0; k < x0.size(); ++k)  // a segment of length 0 is none
    if (x0[k] != x1[k] || y0[k] != y1[k]) s.cracks.push_back({x0[k], y0[k], x1[k], y1[k]});
  s.material = kindOf(kMaterialFieldValues, v.scalar<std::int64_t>(PERISTEP_VR_MATERIAL_FIELD), "material field");
  s.model = kindOf(kSpecimenModelValues, v.scalar<std::int64_t>(PERISTEP_VR_SPECIMEN_MODEL), "specimen model");
  s.exactSolution = kindOf(kExactSolutionValues, v.scalar<std::int64_t>(PERISTEP_VR_EXACT_SOLUTION), "exact solution");
  // Per side: the grip's enumeration, its displacement (x, y) and its velocity (x, y) at loadFactor 1.
  const fmi3ValueReference grips[4][5] = {
      {PERISTEP_VR_GRIP_LEFT, PERISTEP_VR_GRIP_LEFT_UX, PERISTEP_VR_GRIP_LEFT_UY, PERISTEP_VR_GRIP_LEFT_VX,
       PERISTEP_VR_GRIP_LEFT_VY},
      {PERISTEP_VR_GRIP_RIGHT, PERISTEP_VR_GRIP_RIGHT_UX, PERISTEP_VR_GRIP_RIGHT_UY, PERISTEP_VR_GRIP_RIGHT_VX,
       PERISTEP_VR_GRIP_RIGHT_VY},
      {PERISTEP_VR_GRIP_BOTTOM, PERISTEP_VR_GRIP_BOTTOM_UX, PERISTEP_VR_GRIP_BOTTOM_UY, PERISTEP_VR_GRIP_BOTTOM_VX,
       PERISTEP_VR_GRIP_BOTTOM_VY},
      {PERISTEP_VR_GRIP_TOP, PERISTEP_VR_GRIP_TOP_UX, PERISTEP_VR_GRIP_TOP_UY, PERISTEP_VR_GRIP_TOP_VX,
       PERISTEP_VR_GRIP_TOP_VY}};
  for (std::size_t k = 0; k < 4; ++k) {
    const std::int64_t grip = v.scalar<std::int64_t>(grips[k][0]);
    s.grips[k] = {grip != PERISTEP_GRIP_FREE, v.scalar<double>(grips[k][1]), v.scalar<double>(grips[k][2]),
                  v.scalar<double>(grips[k][3]), v.scalar<double>(grips[k][4]), heldComponents(grip)};
  }
  const auto hold = v.get<std::int64_t>(PERISTEP_VR_GRIP_BOX_HOLD);
  const auto bx0 = v.get<double>(PERISTEP_VR_GRIP_BOX_X0), by0 = v.get<double>(PERISTEP_VR_GRIP_BOX_Y0);
  const auto bx1 = v.get<double>(PERISTEP_VR_GRIP_BOX_X1), by1 = v.get<double>(PERISTEP_VR_GRIP_BOX_Y1);
  const auto bvx = v.get<double>(PERISTEP_VR_GRIP_BOX_VX), bvy = v.get<double>(PERISTEP_VR_GRIP_BOX_VY);
  for (std::size_t b = 0; b < hold.size(); ++b)  // a free box is none
    if (hold[b] != PERISTEP_GRIP_FREE)
      s.boxes.push_back({bx0[b], by0[b], bx1[b], by1[b], bvx[b], bvy[b], heldComponents(hold[b])});
  s.bodyForceRateX = nonZero(v.get<double>(PERISTEP_VR_BODY_FORCE_RATE_X));
  s.bodyForceRateY = nonZero(v.get<double>(PERISTEP_VR_BODY_FORCE_RATE_Y));
  s.collarGradient = {v.scalar<double>(PERISTEP_VR_COLLAR_DUX_DX), v.scalar<double>(PERISTEP_VR_COLLAR_DUX_DY),
                      v.scalar<double>(PERISTEP_VR_COLLAR_DUY_DX), v.scalar<double>(PERISTEP_VR_COLLAR_DUY_DY)};
  return s;
}

const std::array<ComputedVariable, 34> kComputed{{
    {PERISTEP_VR_XI_DISTRIBUTION, Needs::Parameters, nullptr,
     [](P p, M, std::span<std::int32_t> out) {
       const SceneParameters s = sceneParameters(p);
       for (std::size_t k = 0; k < out.size(); ++k) out[k] = static_cast<std::int32_t>(xiDistribution(s, k));
     }},
    // Needs the model: the PCA field's scales are its variances.
    {PERISTEP_VR_XI_SCALE, Needs::Model, [](P, M m, std::span<double> out) { copyField(m->xiScales(), out); }},
    {PERISTEP_VR_X, Needs::Model, [](P, M m, std::span<double> out) { copyField(m->x(), out); }},
    {PERISTEP_VR_Y, Needs::Model, [](P, M m, std::span<double> out) { copyField(m->y(), out); }},
    {PERISTEP_VR_UX, Needs::Solution, [](P, M m, std::span<double> out) { copyField(m->ux(), out); }},
    {PERISTEP_VR_UY, Needs::Solution, [](P, M m, std::span<double> out) { copyField(m->uy(), out); }},
    {PERISTEP_VR_DAMAGE, Needs::Solution, [](P, M m, std::span<double> out) { copyField(m->damage(), out); }},
    {PERISTEP_VR_YOUNGS_MODULUS, Needs::Model,
     [](P, M m, std::span<double> out) { copyField(m->youngsModulus(), out); }},
    {PERISTEP_VR_REACTION_FORCE, Needs::Solution, [](P, M m, std::span<double> out) { out[0] = m->reactionForce(); }},
    {PERISTEP_VR_CRACK_LENGTH, Needs::Solution, [](P, M m, std::span<double> out) { out[0] = m->crackLength(); }},
    {PERISTEP_VR_BROKEN_BONDS, Needs::Solution, [](P, M m, std::span<double> out) { out[0] = m->brokenBonds(); }},
    {PERISTEP_VR_STRAIN_ENERGY, Needs::Solution, [](P, M m, std::span<double> out) { out[0] = m->strainEnergy(); }},
    {PERISTEP_VR_FRACTURE_ENERGY, Needs::Solution,
     [](P, M m, std::span<double> out) { out[0] = m->fractureEnergy(); }},
    {PERISTEP_VR_TOUGHNESS_KIC, Needs::Solution, [](P, M m, std::span<double> out) { out[0] = m->toughnessKIC(); }},
    {PERISTEP_VR_ERROR_L2, Needs::Solution, [](P, M m, std::span<double> out) { out[0] = m->errorL2(); }},
    {PERISTEP_VR_EXACT_MEAN_UX, Needs::Solution, [](P, M m, std::span<double> out) { exactMoment(m, 0, out); },
     nullptr, true},
    {PERISTEP_VR_EXACT_MEAN_UY, Needs::Solution, [](P, M m, std::span<double> out) { exactMoment(m, 1, out); },
     nullptr, true},
    {PERISTEP_VR_EXACT_STD_UX, Needs::Solution, [](P, M m, std::span<double> out) { exactMoment(m, 2, out); },
     nullptr, true},
    {PERISTEP_VR_EXACT_STD_UY, Needs::Solution, [](P, M m, std::span<double> out) { exactMoment(m, 3, out); },
     nullptr, true},
    {PERISTEP_VR_HAS_EXACT_MOMENTS, Needs::Model, nullptr,
     [](P, M m, std::span<std::int32_t> out) { out[0] = m->hasExactMoments() ? 1 : 0; }},
    {PERISTEP_VR_RETAINED_VARIANCE, Needs::Model,
     [](P, M m, std::span<double> out) { out[0] = m->retainedVariance(); }},
    {PERISTEP_VR_KINETIC_ENERGY, Needs::Solution, [](P, M m, std::span<double> out) { out[0] = m->kineticEnergy(); }},
    {PERISTEP_VR_EXTERNAL_WORK, Needs::Solution, [](P, M m, std::span<double> out) { out[0] = m->externalWork(); }},
    {PERISTEP_VR_FORCE_EVALUATIONS, Needs::Solution,
     [](P, M m, std::span<double> out) { out[0] = m->forceEvaluations(); }},
    {PERISTEP_VR_REACTION_LEFT_X, Needs::Solution, gripReaction<Side::Left, 0>},
    {PERISTEP_VR_REACTION_LEFT_Y, Needs::Solution, gripReaction<Side::Left, 1>},
    {PERISTEP_VR_REACTION_RIGHT_X, Needs::Solution, gripReaction<Side::Right, 0>},
    {PERISTEP_VR_REACTION_RIGHT_Y, Needs::Solution, gripReaction<Side::Right, 1>},
    {PERISTEP_VR_REACTION_BOTTOM_X, Needs::Solution, gripReaction<Side::Bottom, 0>},
    {PERISTEP_VR_REACTION_BOTTOM_Y, Needs::Solution, gripReaction<Side::Bottom, 1>},
    {PERISTEP_VR_REACTION_TOP_X, Needs::Solution, gripReaction<Side::Top, 0>},
    {PERISTEP_VR_REACTION_TOP_Y, Needs::Solution, gripReaction<Side::Top, 1>},
    {PERISTEP_VR_GRIP_BOX_REACTION_X, Needs::Solution, boxReactions<0>},
    {PERISTEP_VR_GRIP_BOX_REACTION_Y, Needs::Solution, boxReactions<1>},
}};

}  // namespace

SceneParameters sceneParameters(const ParameterValues& v) {
  SceneParameters p;
  p.scene = static_cast<SceneId>(v.scalar<std::int64_t>(PERISTEP_VR_SCENE));  // an item of the registry
  p.grid.nx = static_cast<std::size_t>(v.scalar<std::uint64_t>(PERISTEP_VR_NX));
  p.grid.ny = static_cast<std::size_t>(v.scalar<std::uint64_t>(PERISTEP_VR_NY));
  p.grid.Lx = v.scalar<double>(PERISTEP_VR_LX);
  p.grid.Ly = v.scalar<double>(PERISTEP_VR_LY);
  p.grid.deltaOverH = v.scalar<double>(PERISTEP_VR_DELTA_OVER_H);
  p.grid.jitter = v.scalar<double>(PERISTEP_VR_JITTER);
  p.grid.seed = v.scalar<std::uint64_t>(PERISTEP_VR_SEED);
  p.poissonRatio = v.scalar<double>(PERISTEP_VR_POISSON_RATIO);
  p.modulusContrast = v.scalar<double>(PERISTEP_VR_MODULUS_CONTRAST);
  p.crystalFraction = v.scalar<double>(PERISTEP_VR_CRYSTAL_FRACTION);
  p.pcaRealizations = static_cast<std::size_t>(v.scalar<std::uint64_t>(PERISTEP_VR_PCA_REALIZATIONS));
  p.covariance = kindOf(kCovarianceValues, v.scalar<std::int64_t>(PERISTEP_VR_COVARIANCE), "covariance");
  p.correlationLength = v.scalar<double>(PERISTEP_VR_CORRELATION_LENGTH);
  p.fieldStd = v.scalar<double>(PERISTEP_VR_FIELD_STD);
  p.transform = kindOf(kFieldTransformValues, v.scalar<std::int64_t>(PERISTEP_VR_FIELD_TRANSFORM), "field transform");
  const auto xi = v.get<double>(PERISTEP_VR_XI);
  p.xi.assign(xi.begin(), xi.end());
  p.linearSolver = kindOf(kLinearSolverValues, v.scalar<std::int64_t>(PERISTEP_VR_LINEAR_SOLVER), "linear solver");
  p.timeIntegrator =
      kindOf(kTimeIntegratorValues, v.scalar<std::int64_t>(PERISTEP_VR_TIME_INTEGRATOR), "time integrator");
  p.internalTimeStep = v.scalar<double>(PERISTEP_VR_INTERNAL_TIME_STEP);
  p.integratorTolerance = v.scalar<double>(PERISTEP_VR_INTEGRATOR_TOLERANCE);
  p.glassYoungsModulus = v.scalar<double>(PERISTEP_VR_GLASS_YOUNGS_MODULUS);
  p.crystalYoungsModulus = v.scalar<double>(PERISTEP_VR_CRYSTAL_YOUNGS_MODULUS);
  p.glassFractureEnergy = v.scalar<double>(PERISTEP_VR_GLASS_FRACTURE_ENERGY);
  p.crystalFractureEnergy = v.scalar<double>(PERISTEP_VR_CRYSTAL_FRACTURE_ENERGY);
  p.bulkModulus = v.scalar<double>(PERISTEP_VR_BULK_MODULUS);
  p.criticalEnergyReleaseRate = v.scalar<double>(PERISTEP_VR_CRITICAL_ENERGY_RELEASE_RATE);
  p.density = v.scalar<double>(PERISTEP_VR_DENSITY);
  if (p.scene == SceneId::Specimen) p.specimen = specimen(v);
  const SceneDeclaration* scene = findScene(p.scene);
  if (!scene) throw InvalidInput("unknown scene " + std::to_string(static_cast<std::int64_t>(p.scene)));
  for (const Variable& own : scene->variables)
    if (settable(own)) p.own[own.vr] = asDoubles(v, own);
  if (scene->configure) scene->configure(p);
  // memoryBudget 0: 3/4 of what the process can use, leaving room for the importer and other instances.
  const auto budget = v.scalar<std::uint64_t>(PERISTEP_VR_MEMORY_BUDGET);
  p.limits.memoryBytes = budget > 0 ? static_cast<double>(budget) : 0.75 * static_cast<double>(usableMemoryBytes());
  p.limits.setUpSeconds = v.scalar<double>(PERISTEP_VR_SET_UP_TIME_LIMIT);
  p.limits.internalSteps = v.scalar<std::uint64_t>(PERISTEP_VR_MAX_INTERNAL_STEPS);
  return p;
}

namespace {

// The computed variables of the shared table and of every scene's own outputs.
const std::vector<ComputedVariable>& computedVariables() {
  static const std::vector<ComputedVariable> all = [] {
    std::vector<ComputedVariable> c(kComputed.begin(), kComputed.end());
    for (ComputedVariable& o : ownOutputs()) c.push_back(std::move(o));
    return c;
  }();
  return all;
}

}  // namespace

std::string firstNonFinite(const ParameterValues& values, const SceneModel& model, Needs needs) {
  std::vector<double> buffer;
  for (const ComputedVariable& c : computedVariables()) {
    if (c.needs != needs || !c.readFloat64 || c.onRequest) continue;
    const Variable& v = *findVariable(c.vr);
    buffer.resize(values.size(v));
    c.readFloat64(values, &model, buffer);
    for (std::size_t k = 0; k < buffer.size(); ++k)
      if (!std::isfinite(buffer[k]))
        return std::string(v.name) + (buffer.size() > 1 ? "[" + std::to_string(k) + "]" : "") + " = " +
               numberText(buffer[k]);
  }
  return {};
}

const ComputedVariable* findComputed(fmi3ValueReference vr) {
  const auto& all = computedVariables();
  const auto it = std::find_if(all.begin(), all.end(), [vr](const auto& c) { return c.vr == vr; });
  return it == all.end() ? nullptr : &*it;
}

}  // namespace peristep::fmi
