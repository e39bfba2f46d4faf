// Streamed PCA of realizations (random/microstructure_pca.hpp) against the dense sample covariance of
// the same realizations, and the process-wide cache of modes (random/pca_cache.hpp).
#include <catch2/catch.hpp>

#include <atomic>
#include <omp.h>
#include <random>
#include <thread>
#include <vector>

#include "core/errors.hpp"
#include "geometry/point_cloud.hpp"
#include "random/microstructure_pca.hpp"
#include "random/pca_cache.hpp"
#include "random/randomized_eigen.hpp"
#include "scenes/microstructure.hpp"

using namespace peristep;

namespace {

// Everything a dense PCA of the same n realizations gives, from the n x M data matrix in memory.
struct DensePca {
  Eigen::MatrixXd data;  // n x M
  Eigen::VectorXd mean;
  EigenPairs pairs;      // all pairs, descending
  double trace = 0;
  DensePca(std::size_t M, std::size_t n, const RealizationGenerator& generate) : data(n, M) {
    std::vector<double> row(M);
    for (std::size_t j = 0; j < n; ++j) {
      generate(j, row);
      for (std::size_t i = 0; i < M; ++i) data(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(i)) = row[i];
    }
    mean = data.colwise().mean().transpose();
    const Eigen::MatrixXd centred = data.rowwise() - mean.transpose();
    const Eigen::MatrixXd C = centred.transpose() * centred / static_cast<double>(n - 1);
    trace = C.trace();
    pairs = denseEigen(C, M);
  }
};

double subspaceSine(const Eigen::MatrixXd& U, const Eigen::MatrixXd& W) {
  const Eigen::MatrixXd R = W - U * (U.transpose() * W);
  return Eigen::JacobiSVD<Eigen::MatrixXd>(R).singularValues()(0);
}

// A binary field of known structure on a 20 x 20 grid: four disjoint blocks, each switched on with
// its own probability, plus bits flipped with probability 2 %. Realization j depends on j alone.
void blockField(std::size_t j, std::span<double> out) {
  std::mt19937_64 rng(1000 + j);
  const auto uniform = [&rng] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  const double probability[4] = {0.5, 0.3, 0.6, 0.2};
  bool on[4];
  for (int b = 0; b < 4; ++b) on[b] = uniform() < probability[b];
  for (std::size_t p = 0; p < out.size(); ++p) {
    const std::size_t i = p % 20, k = p / 20;
    const int block = k < 10 ? (i < 10 ? 0 : 1) : (i < 8 ? 2 : (i < 14 ? 3 : -1));
    double v = block >= 0 && on[block] ? 1.0 : 0.0;
    if (uniform() < 0.02) v = 1.0 - v;
    out[p] = v;
  }
}

}  // namespace

TEST_CASE("streamed PCA of a block field matches the dense sample covariance", "[random][pca]") {
  const std::size_t M = 400, n = 300;
  const DensePca dense(M, n, blockField);
  PcaSpec spec{M, n, 4, 8, 3, 5};
  const PcaModes pca = streamedPca(spec, blockField);
  INFO("dense eigenvalues 1-6: " << dense.pairs.values.head(6).transpose());
  REQUIRE(dense.pairs.values[3] > 50 * dense.pairs.values[4]);  // the gap the test relies on

  CHECK(pca.passes == spec.powerIterations + 2);
  CHECK((pca.mean - dense.mean).cwiseAbs().maxCoeff() < 1e-14);
  CHECK(pca.totalVariance == Approx(dense.trace).epsilon(1e-12));
  for (Eigen::Index k = 0; k < 4; ++k) CHECK(pca.variances[k] == Approx(dense.pairs.values[k]).epsilon(1e-10));
  // Expected sin ~ (lambda_13 / lambda_4)^(q + 1) = (0.09 / 8.1)^4 ~ 2e-8.
  CHECK(subspaceSine(dense.pairs.vectors.leftCols(4), pca.modes) < 1e-6);
  CHECK((pca.modes.transpose() * pca.modes - Eigen::MatrixXd::Identity(4, 4)).cwiseAbs().maxCoeff() < 1e-13);
  CHECK(pca.retainedFraction() == Approx(dense.pairs.values.head(4).sum() / dense.trace).epsilon(1e-10));

  // 000:(5.5) read as xi_k ~ N(0, lambda_k): the PCA scores a_jk = V_k^T (x_j - m) of (5.4) have sample
  // variance lambda_k, the eigenvalue itself (not its square).
  const Eigen::MatrixXd scores = (dense.data.rowwise() - dense.mean.transpose()) * pca.modes;
  for (Eigen::Index k = 0; k < 4; ++k)
    CHECK(scores.col(k).squaredNorm() / static_cast<double>(n - 1) == Approx(pca.variances[k]).epsilon(1e-10));
}

TEST_CASE("streamed PCA of glass-ceramic microstructures matches the dense PCA", "[random][pca]") {
  // 000:(5.1) crystal indicator on a small free-edged grid (h = 4 um, 25 x 13 = 325 values), f = 0.3.
  GridSpec grid{25, 13, 96e-6, 48e-6, 3.0};
  grid.collar = false;
  const PointCloud cloud = makeRectangle(grid);
  const RealizationGenerator crystals = [&cloud](std::size_t j, std::span<double> out) {
    const std::vector<std::uint8_t> R = generateMicrostructure(cloud, 0.3, 500 + j);
    for (std::size_t p = 0; p < R.size(); ++p) out[p] = R[p];
  };
  const std::size_t M = cloud.size(), n = 400, k = 3;
  const DensePca dense(M, n, crystals);
  const Eigen::VectorXd& lambda = dense.pairs.values;
  INFO("dense eigenvalues 1-8: " << lambda.head(8).transpose());
  REQUIRE(lambda[k - 1] > 1.05 * lambda[k]);  // gap after mode k for this seed range

  // l = k + 20 vectors, 12 subspace iterations: sin ~ (lambda_24 / lambda_3)^13 for this slowly decaying spectrum.
  const PcaModes pca = streamedPca({M, n, k, 20, 12, 9}, crystals);
  const double sine = subspaceSine(dense.pairs.vectors.leftCols(static_cast<Eigen::Index>(k)), pca.modes);
  const double rel = ((pca.variances - lambda.head(static_cast<Eigen::Index>(k))).array() /
                      lambda.head(static_cast<Eigen::Index>(k)).array()).abs().maxCoeff();
  WARN("glass-ceramic PCA, " << n << " realizations of " << M << " values, lambda_(k+21)/lambda_k = "
                             << lambda[k + 20] / lambda[k - 1] << ": sin(subspace angle) " << sine
                             << ", max relative eigenvalue error " << rel << ", retained variance with " << k
                             << " modes " << pca.retainedFraction() << " (dense: "
                             << lambda.head(static_cast<Eigen::Index>(k)).sum() / dense.trace << ")");
  CHECK(sine < 1e-6);
  CHECK(rel < 1e-8);
  CHECK(pca.totalVariance == Approx(dense.trace).epsilon(1e-12));
  CHECK(pca.retainedFraction() == Approx(lambda.head(static_cast<Eigen::Index>(k)).sum() / dense.trace).epsilon(1e-8));
  CHECK((pca.mean - dense.mean).cwiseAbs().maxCoeff() < 1e-14);
}

TEST_CASE("streamed PCA gives identical results on 1 and 2 threads", "[random][pca]") {
  const PcaSpec spec{400, 333, 4, 6, 2, 8};  // 333: the last chunk is partial
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  const PcaModes one = streamedPca(spec, blockField);
  omp_set_num_threads(2);
  const PcaModes two = streamedPca(spec, blockField);
  omp_set_num_threads(saved);
  CHECK(one.mean == two.mean);
  CHECK(one.variances == two.variances);
  CHECK(one.modes == two.modes);
  CHECK(one.totalVariance == two.totalVariance);
}

TEST_CASE("streamed PCA: expansion, invalid specs and generator errors", "[random][pca]") {
  const PcaModes pca = streamedPca({400, 200, 3, 5, 2, 1}, blockField);
  CHECK(pca.expand(std::vector<double>{0.0, 0.0, 0.0}) == pca.mean);
  const Eigen::VectorXd e2 = pca.expand(std::vector<double>{0.0, 2.0, 0.0});
  CHECK((e2 - pca.mean - 2.0 * std::sqrt(pca.variances[1]) * pca.modes.col(1)).cwiseAbs().maxCoeff() < 1e-14);
  CHECK_THROWS_AS(pca.expand(std::vector<double>{0.0, 1.0}), InvalidInput);

  CHECK_THROWS_AS(streamedPca({400, 1, 3, 5, 2, 1}, blockField), InvalidInput);
  CHECK_THROWS_AS(streamedPca({400, 200, 0, 5, 2, 1}, blockField), InvalidInput);
  CHECK_THROWS_AS(streamedPca({0, 200, 3, 5, 2, 1}, blockField), InvalidInput);
  CHECK_THROWS_AS(streamedPca({400, 200, 3, 5, 2, 1}, RealizationGenerator{}), InvalidInput);
  // An exception thrown by the generator inside the parallel loop reaches the caller intact.
  const RealizationGenerator failing = [](std::size_t j, std::span<double> out) {
    if (j == 137) throw InvalidInput("realization 137 cannot be generated");
    blockField(j, out);
  };
  CHECK_THROWS_WITH(streamedPca({400, 200, 3, 5, 2, 1}, failing), "realization 137 cannot be generated");
  const RealizationGenerator nan = [](std::size_t j, std::span<double> out) {
    blockField(j, out);
    if (j == 5) out[3] = std::nan("");
  };
  CHECK_THROWS_AS(streamedPca({400, 200, 3, 5, 2, 1}, nan), SolverFailure);
}

TEST_CASE("PCA cache computes each key once and shares the modes", "[random][pca][cache]") {
  clearPcaCache();
  std::atomic<int> computed{0};
  const auto compute = [&computed] {
    ++computed;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));  // let the other threads arrive meanwhile
    return streamedPca({400, 100, 2, 4, 1, 1}, blockField);
  };
  CHECK(findCachedPca("block f=0.5 n=100") == nullptr);
  std::vector<std::shared_ptr<const PcaModes>> got(4);
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < got.size(); ++t)
    threads.emplace_back([&, t] { got[t] = cachedPca("block f=0.5 n=100", compute); });
  for (auto& t : threads) t.join();
  CHECK(computed == 1);
  for (const auto& g : got) CHECK(g == got[0]);
  CHECK(findCachedPca("block f=0.5 n=100") == got[0]);
  CHECK(cachedPca("other key", compute) != got[0]);
  CHECK(computed == 2);
  CHECK(pcaCacheSize() == 2);

  // A failed computation is reported and not stored: the next request computes again.
  const auto failing = []() -> PcaModes { throw InvalidInput("no realizations"); };
  CHECK_THROWS_WITH(cachedPca("failing", failing), "no realizations");
  CHECK(findCachedPca("failing") == nullptr);
  CHECK(cachedPca("failing", compute) != nullptr);
  CHECK(computed == 3);

  clearPcaCache();
  CHECK(pcaCacheSize() == 0);
  CHECK(got[0]->size() == 2);  // held modes outlive the cache entry
}
