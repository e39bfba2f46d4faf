// Monte Carlo standard errors of host/sample_statistics (se of the mean s/sqrt(Q), of the variance
// sqrt((m4 - m2^2)/Q), of the std by the delta method): by hand on four numbers, and against the spread of
// the estimates over many independent Monte Carlo studies of known laws.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "sample_statistics.hpp"
#include "sampling/monte_carlo.hpp"

using namespace peristep;
using namespace peristep::host;

namespace {

Moments monteCarloMoments(const std::vector<std::vector<double>>& samples) {
  std::vector<const std::vector<double>*> values;
  for (const auto& s : samples) values.push_back(&s);
  Moments m = weightedMoments(values, std::vector<double>(samples.size(), 1.0 / static_cast<double>(samples.size())));
  addStandardErrors(m, values);
  return m;
}

double spread(const std::vector<double>& v) {
  double mean = 0, square = 0;
  for (double x : v) mean += x / static_cast<double>(v.size());
  for (double x : v) square += (x - mean) * (x - mean) / static_cast<double>(v.size() - 1);
  return std::sqrt(square);
}

}  // namespace

TEST_CASE("sampling statistics: Monte Carlo standard errors by hand on the samples 1 2 3 4", "[host][sample][statistics]") {
  const Moments m = monteCarloMoments({{1}, {2}, {3}, {4}});
  CHECK(m.mean[0] == 2.5);
  CHECK(m.std[0] == Approx(std::sqrt(1.25)).epsilon(1e-15));               // m2 = 5/4
  CHECK(m.seMean[0] == Approx(std::sqrt(5.0 / 3.0 / 4.0)).epsilon(1e-15));  // s^2 = 5/3
  CHECK(m.seVar[0] == Approx(0.5).epsilon(1e-15));                          // m4 = 41/16: sqrt((41/16 - 25/16)/4)
  CHECK(m.seStd[0] == Approx(0.5 / (2 * std::sqrt(1.25))).epsilon(1e-15));
  CHECK(std::isnan(monteCarloMoments({{1}}).seMean[0]));  // one sample: no standard error
}

TEST_CASE("sampling statistics: Monte Carlo standard errors match the spread over 4000 repeated studies",
          "[host][sample][statistics]") {
  // Q = 50 samples of x ~ N(0,1) (Var[m2] ~ 2/Q) and of x ~ U[-1,1] (Var[m2] ~ (1/5 - 1/9)/Q) per study.
  for (const sampling::Law law : {sampling::Law::Normal, sampling::Law::Uniform}) {
    const std::size_t studies = 4000, Q = 50;
    const double trueMean = 0;
    std::vector<double> means, variances, stds, seMean, seVar, seStd;
    std::size_t covered = 0;
    for (std::size_t s = 0; s < studies; ++s) {
      const sampling::SampleSet set = sampling::monteCarlo(std::vector<sampling::Law>{law}, Q, 1000 + s);
      std::vector<std::vector<double>> samples;
      for (std::size_t k = 0; k < Q; ++k) samples.push_back({set.point(k)[0]});
      const Moments m = monteCarloMoments(samples);
      means.push_back(m.mean[0]);
      variances.push_back(m.std[0] * m.std[0]);
      stds.push_back(m.std[0]);
      seMean.push_back(m.seMean[0]);
      seVar.push_back(m.seVar[0]);
      seStd.push_back(m.seStd[0]);
      covered += std::abs(m.mean[0] - trueMean) <= interval95(m.seMean[0]);
    }
    const auto average = [](const std::vector<double>& v) {
      double a = 0;
      for (double x : v) a += x / static_cast<double>(v.size());
      return a;
    };
    INFO((law == sampling::Law::Normal ? "normal" : "uniform"));
    // The standard errors a single study reports, on average, are the spread of the estimates themselves
    // (the spread is known to ~1.1% from 4000 studies; the large-Q variance formula is 1/Q-accurate).
    CHECK(average(seMean) == Approx(spread(means)).epsilon(0.04));
    CHECK(average(seVar) == Approx(spread(variances)).epsilon(0.08));
    CHECK(average(seStd) == Approx(spread(stds)).epsilon(0.08));
    // ... and against the law's own values: sigma/sqrt(Q) and sqrt((mu4 - sigma^4)/Q).
    const double sigma2 = law == sampling::Law::Normal ? 1.0 : 1.0 / 3.0, mu4 = law == sampling::Law::Normal ? 3.0 : 0.2;
    CHECK(average(seMean) == Approx(std::sqrt(sigma2 / Q)).epsilon(0.02));
    CHECK(average(seVar) == Approx(std::sqrt((mu4 - sigma2 * sigma2) / Q)).epsilon(0.08));
    // The 95% interval of the mean covers the true mean in 95% of the studies (normal quantile at Q = 50:
    // a little under, ~94.4%; +-1% is three binomial standard deviations of the count).
    CHECK(static_cast<double>(covered) / studies == Approx(0.945).margin(0.012));
  }
}
