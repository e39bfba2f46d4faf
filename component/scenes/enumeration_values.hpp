#pragma once
// The enumeration value (api/peristep.h, modelDescription.xml) of every option that selects C++ code: the
// one place where the two are paired. Names and descriptions come from the option's table
// (core/option_table.hpp), beside the code it selects. The variable declarations take the <Item>s from here
// and the parameters read by name turn the value an importer set into the C++ value, so an option is never
// spelled as a string between the two.
#include <array>
#include <cstdint>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "core/errors.hpp"
#include "core/option_table.hpp"
#include "core/variable_declaration.hpp"
#include "scenes/scene_model.hpp"

namespace peristep {

template <class Kind>
struct EnumerationValue {
  std::int64_t value;
  Kind kind;
};

inline constexpr std::array<EnumerationValue<SpecimenModel>, 3> kSpecimenModelValues{{
    {1, SpecimenModel::QuasiStatic},
    {2, SpecimenModel::Dynamic},
    {3, SpecimenModel::Elastic},
}};

inline constexpr std::array<EnumerationValue<ExactSolution>, 4> kExactSolutionValues{{
    {1, ExactSolution::None},
    {2, ExactSolution::Smooth},
    {3, ExactSolution::Composite},
    {4, ExactSolution::InterfaceCrack},
}};

inline constexpr std::array<EnumerationValue<SpecimenMaterial>, 3> kMaterialFieldValues{{
    {1, SpecimenMaterial::Maps},
    {2, SpecimenMaterial::KlField},
    {3, SpecimenMaterial::GlassCeramic},
}};

inline constexpr std::array<EnumerationValue<LinearSolverKind>, 4> kLinearSolverValues{{
    {1, LinearSolverKind::Umfpack},
    {2, LinearSolverKind::UmfpackAmd},
    {3, LinearSolverKind::SparseLu},
    {4, LinearSolverKind::BicgstabIlut},
}};

inline constexpr std::array<EnumerationValue<TimeIntegratorKind>, 3> kTimeIntegratorValues{{
    {1, TimeIntegratorKind::CentralDifference},
    {2, TimeIntegratorKind::ArkodeErk},
    {3, TimeIntegratorKind::CvodeBdf},
}};

inline constexpr std::array<EnumerationValue<CovarianceKind>, 2> kCovarianceValues{{
    {1, CovarianceKind::Exponential},
    {2, CovarianceKind::Gaussian},
}};

inline constexpr std::array<EnumerationValue<MaterialTransform>, 2> kFieldTransformValues{{
    {1, MaterialTransform::Affine},
    {2, MaterialTransform::Positive},
}};

// The C++ value of an enumeration value; the variable table refuses other values when they are set, so
// an unknown one here is an internal error.
template <class Kind, std::size_t N>
Kind kindOf(const std::array<EnumerationValue<Kind>, N>& values, std::int64_t value, std::string_view what) {
  for (const EnumerationValue<Kind>& v : values)
    if (v.value == value) return v.kind;
  throw InvalidInput("unknown " + std::string(what) + " " + std::to_string(value));
}

// The <Item>s of an enumeration type: names and descriptions from the option table, in the order of values.
template <class Kind, std::size_t N>
std::vector<EnumerationItem> enumerationItems(const std::array<EnumerationValue<Kind>, N>& values,
                                              const std::array<Option<Kind>, N>& options) {
  std::vector<EnumerationItem> items;
  for (const EnumerationValue<Kind>& v : values) {
    const Option<Kind>& o = option(options, v.kind);
    items.push_back({o.name, v.value, o.description});
  }
  return items;
}

}  // namespace peristep
