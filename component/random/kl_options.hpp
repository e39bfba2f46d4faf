#pragma once
// The options of a KL material field, carried as these values from the FMI variables covariance and
// fieldTransform to random/kl_field.hpp.
#include <array>

#include "core/option_table.hpp"

namespace peristep {

enum class CovarianceKind {
  Exponential,  // s^2 exp(-r / l)
  Gaussian,     // s^2 exp(-r^2 / l^2)
};

inline constexpr std::array<Option<CovarianceKind>, 2> kCovarianceOptions{{
    {CovarianceKind::Exponential, "exponential", "s^2 exp(-r/l)"},
    {CovarianceKind::Gaussian, "gaussian", "s^2 exp(-r^2/l^2)"},
}};

// How a zero-mean field g becomes a material parameter with mean value E0.
enum class MaterialTransform {
  Affine,    // E = E0 (1 + g): linear in xi, but not positive for large |xi| (rejected with a message)
  Positive,  // E = E0 exp(g - v(x)/2): lognormal, positive for every xi, mean E0 (see materialField)
};

inline constexpr std::array<Option<MaterialTransform>, 2> kMaterialTransformOptions{{
    {MaterialTransform::Affine, "affine", "E = E0 (1 + g); a sample with E <= 0 anywhere is refused"},
    {MaterialTransform::Positive, "lognormal", "E = E0 exp(g - var/2): positive for every xi, mean E0"},
}};

}  // namespace peristep
