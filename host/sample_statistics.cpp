#include "sample_statistics.hpp"

#include <cmath>
#include <limits>

#include "host_errors.hpp"

namespace peristep::host {

Moments weightedMoments(const std::vector<const std::vector<double>*>& values, const std::vector<double>& weights) {
  if (values.empty() || values.size() != weights.size())
    throw RunError("moments need one weight per sample (" + std::to_string(weights.size()) + " weights, " +
                   std::to_string(values.size()) + " samples)");
  const std::size_t n = values.front()->size();
  Moments m;
  m.mean.assign(n, 0.0);
  m.std.assign(n, 0.0);
  for (std::size_t k = 0; k < values.size(); ++k)
    for (std::size_t i = 0; i < n; ++i) m.mean[i] += weights[k] * (*values[k])[i];  // 000:(3.10)
  for (std::size_t k = 0; k < values.size(); ++k)
    for (std::size_t i = 0; i < n; ++i) {
      const double d = (*values[k])[i] - m.mean[i];
      m.std[i] += weights[k] * d * d;  // 000:(3.11)
    }
  for (double& v : m.std) {
    if (v < 0) ++m.clamped;
    v = std::sqrt(std::max(v, 0.0));
  }
  return m;
}

void addPceStd(Moments& m, const std::vector<const std::vector<double>*>& values,
               const sampling::SparseProjection& projection) {
  const std::size_t n = values.front()->size();
  std::vector<double> c(projection.coefficients * n, 0.0);
  for (const sampling::SpectralTerm& t : projection.terms) {
    const std::vector<double>& q = *values.at(t.sample);
    for (std::size_t i = 0; i < n; ++i) c[t.coefficient * n + i] += t.factor * q[i];
  }
  m.pceStd.assign(n, 0.0);
  for (std::size_t a = 1; a < projection.coefficients; ++a)  // a = 0 is the mean
    for (std::size_t i = 0; i < n; ++i) m.pceStd[i] += c[a * n + i] * c[a * n + i];
  for (double& v : m.pceStd) v = std::sqrt(v);
}

void addStandardErrors(Moments& m, const std::vector<const std::vector<double>*>& values) {
  const std::size_t n = m.mean.size();
  const double q = static_cast<double>(values.size());
  std::vector<double> m4(n, 0.0);
  for (const std::vector<double>* v : values)
    for (std::size_t i = 0; i < n; ++i) {
      const double d = (*v)[i] - m.mean[i];
      m4[i] += d * d * d * d / q;
    }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  m.seMean.assign(n, nan);
  m.seVar.assign(n, nan);
  m.seStd.assign(n, nan);
  if (values.size() < 2) return;
  for (std::size_t i = 0; i < n; ++i) {
    const double m2 = m.std[i] * m.std[i];
    m.seMean[i] = std::sqrt(m2 * q / (q - 1) / q);
    m.seVar[i] = std::sqrt(std::max(m4[i] - m2 * m2, 0.0) / q);
    m.seStd[i] = m.std[i] > 0 ? m.seVar[i] / (2 * m.std[i]) : nan;
  }
}

double interval95(double seMean) { return 1.959963984540054 * seMean; }

}  // namespace peristep::host
