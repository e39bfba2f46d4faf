#include "scenes/exact_moments.hpp"

#include <cmath>
#include <functional>

#include "core/parallel_errors.hpp"
#include "random/reference_rules.hpp"
#include "scenes/manufactured.hpp"

namespace peristep {
namespace {

using Field = std::function<Vec2(double x, double y)>;

// The exact local solution at physical random coordinates xi.
Field exactField(const SceneParameters& p, const std::vector<double>& xi) {
  if (exactSolution(p) == ExactSolution::None) return {};
  std::shared_ptr<const ElasticScene> s =
      manufacturedScene(exactSolution(p), p.poissonRatio, xi, p.modulusContrast, p.grid.h());
  return [s](double x, double y) { return s->displacement(x, y); };
}

}  // namespace

std::optional<ExactMoments> exactMoments(const SceneParameters& p, const PointCloud& cloud) {
  const std::size_t modes = randomCoordinates(p);
  if (modes == 0 || !exactField(p, std::vector<double>(modes, 0.0))) return std::nullopt;

  // Tensor product of the reference rules, in physical coordinates.
  std::vector<std::vector<double>> nodes{{}};
  std::vector<double> weights{1.0};
  for (std::size_t k = 0; k < modes; ++k) {
    const ProbabilityRule r =
        xiDistribution(p, k) == XiDistribution::Uniform ? uniformReferenceRule() : normalReferenceRule();
    std::vector<std::vector<double>> n2;
    std::vector<double> w2;
    for (std::size_t a = 0; a < nodes.size(); ++a)
      for (std::size_t b = 0; b < r.nodes.size(); ++b) {
        n2.push_back(nodes[a]);
        n2.back().push_back(xiScale(p, k) * r.nodes[b]);
        w2.push_back(weights[a] * r.weights[b]);
      }
    nodes = std::move(n2);
    weights = std::move(w2);
  }
  std::vector<Field> fields;
  for (const auto& xi : nodes) fields.push_back(exactField(p, xi));
  const Field centre = exactField(p, std::vector<double>(modes, 0.0));

  const std::size_t n = cloud.domain.size();
  ExactMoments m{std::vector<double>(n), std::vector<double>(n), std::vector<double>(n), std::vector<double>(n)};
  ParallelErrors errors;  // the exact fields are opaque callables: whatever they throw stays inside
#pragma omp parallel for schedule(dynamic, 64)
  for (std::size_t i = 0; i < n; ++i) errors.capture([&] {
    const double x = cloud.x[cloud.domain[i]], y = cloud.y[cloud.domain[i]];
    // Sums of the deviation from the value at xi = 0: the variance loses no digits to cancellation.
    const Vec2 c = centre(x, y);
    double s1[2] = {0, 0}, s2[2] = {0, 0};
    for (std::size_t q = 0; q < fields.size(); ++q) {
      const Vec2 u = fields[q](x, y);
      for (int a = 0; a < 2; ++a) {
        const double d = u[static_cast<std::size_t>(a)] - c[static_cast<std::size_t>(a)];
        s1[a] += weights[q] * d;
        s2[a] += weights[q] * d * d;
      }
    }
    m.meanUx[i] = c[0] + s1[0];
    m.meanUy[i] = c[1] + s1[1];
    m.stdUx[i] = std::sqrt(std::max(0.0, s2[0] - s1[0] * s1[0]));
    m.stdUy[i] = std::sqrt(std::max(0.0, s2[1] - s1[1] * s1[1]));
  });
  errors.rethrow();
  return m;
}

}  // namespace peristep
