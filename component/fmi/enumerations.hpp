#pragma once
// The FMI enumeration value (api/peristep.h) of every option the solver side names in its own table
// (core/option_table.hpp): the one place where the two are paired. The variable table takes the <Item>s
// from here and the model binding turns the value an importer set into the C++ value, so an option is never
// spelled as a string between the two.
#include <array>
#include <cstdint>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "core/errors.hpp"
#include "core/option_table.hpp"
#include "fmi/variables.hpp"
#include "peristep.h"
#include "random/kl_options.hpp"
#include "solvers/linear_solver_kind.hpp"
#include "solvers/time_integrator_kind.hpp"

namespace peristep::fmi {

template <class Kind>
struct EnumerationValue {
  std::int64_t value;
  Kind kind;
};

inline constexpr std::array<EnumerationValue<LinearSolverKind>, 4> kLinearSolverValues{{
    {PERISTEP_LINEAR_SOLVER_UMFPACK, LinearSolverKind::Umfpack},
    {PERISTEP_LINEAR_SOLVER_UMFPACK_AMD, LinearSolverKind::UmfpackAmd},
    {PERISTEP_LINEAR_SOLVER_SPARSE_LU, LinearSolverKind::SparseLu},
    {PERISTEP_LINEAR_SOLVER_BICGSTAB_ILUT, LinearSolverKind::BicgstabIlut},
}};

inline constexpr std::array<EnumerationValue<TimeIntegratorKind>, 3> kTimeIntegratorValues{{
    {PERISTEP_INTEGRATOR_CENTRAL_DIFFERENCE, TimeIntegratorKind::CentralDifference},
    {PERISTEP_INTEGRATOR_ARKODE_ERK, TimeIntegratorKind::ArkodeErk},
    {PERISTEP_INTEGRATOR_CVODE_BDF, TimeIntegratorKind::CvodeBdf},
}};

inline constexpr std::array<EnumerationValue<CovarianceKind>, 2> kCovarianceValues{{
    {PERISTEP_COVARIANCE_EXPONENTIAL, CovarianceKind::Exponential},
    {PERISTEP_COVARIANCE_GAUSSIAN, CovarianceKind::Gaussian},
}};

inline constexpr std::array<EnumerationValue<MaterialTransform>, 2> kFieldTransformValues{{
    {PERISTEP_FIELD_AFFINE, MaterialTransform::Affine},
    {PERISTEP_FIELD_LOGNORMAL, MaterialTransform::Positive},
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

}  // namespace peristep::fmi
