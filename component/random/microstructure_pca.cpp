#include "random/microstructure_pca.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/errors.hpp"
#include "core/parallel_errors.hpp"
#include "random/randomized_eigen.hpp"

namespace peristep {
namespace {

// Realizations per chunk: one chunk is generated into an M x 64 block, so both covariance products
// are matrix-matrix products; chunk sums are added in chunk order (thread-count independent result).
constexpr Eigen::Index chunkSize = 64;

// C X = (sum_j x_j x_j^T X - n m m^T X) / (n - 1) by streaming the realizations. The first pass also
// sums x_j and |x_j|^2, giving the mean m and trace C = (sum |x_j|^2 - n |m|^2) / (n - 1) without a
// pass of their own. The subtraction loses about log10(|m|^2 / trace C) digits: none to speak of for
// an indicator with crystal fractions in (0, 1).
class StreamedCovariance {
 public:
  StreamedCovariance(const PcaSpec& spec, const RealizationGenerator& generate) : spec_(spec), generate_(generate) {}

  void apply(const Eigen::MatrixXd& X, Eigen::MatrixXd& CX) {
    const auto M = static_cast<Eigen::Index>(spec_.values), n = static_cast<Eigen::Index>(spec_.realizations);
    const bool firstPass = passes_ == 0;
    const Eigen::Index chunks = (n + chunkSize - 1) / chunkSize;
    Eigen::MatrixXd S = Eigen::MatrixXd::Zero(M, X.cols());
    Eigen::VectorXd sum = Eigen::VectorXd::Zero(firstPass ? M : 0);
    double sumSquares = 0;
    ParallelErrors errors;  // generate_ and the block products allocate

#pragma omp parallel
    {
      Eigen::MatrixXd B, T, P;  // allocated inside capture(): nothing may throw out of the region
      Eigen::VectorXd chunkSum;
      double chunkSquares = 0;
#pragma omp for ordered schedule(static, 1)
      for (Eigen::Index c = 0; c < chunks; ++c) {
        bool done = false;
        errors.capture([&] {
          const Eigen::Index j0 = c * chunkSize, cols = std::min(chunkSize, n - j0);
          B.resize(M, chunkSize);  // no-op after the first chunk
          for (Eigen::Index b = 0; b < cols; ++b)
            generate_(static_cast<std::size_t>(j0 + b), std::span<double>(B.col(b).data(), spec_.values));
          const auto block = B.leftCols(cols);
          T.noalias() = block.transpose() * X;
          P.noalias() = block * T;
          if (firstPass) {
            chunkSum = block.rowwise().sum();
            chunkSquares = block.squaredNorm();
          }
          done = true;
        });
#pragma omp ordered
        if (done) {
          S += P;
          if (firstPass) {
            sum += chunkSum;
            sumSquares += chunkSquares;
          }
        }
      }
    }
    errors.rethrow();
    if (!S.allFinite()) throw SolverFailure("streamed PCA: a realization holds values that are not finite");

    const double nd = static_cast<double>(n);
    if (firstPass) {
      mean_ = sum / nd;
      trace_ = std::max(0.0, (sumSquares - nd * mean_.squaredNorm()) / (nd - 1.0));
    }
    ++passes_;
    CX.noalias() = (S - nd * mean_ * (mean_.transpose() * X)) / (nd - 1.0);
  }

  const Eigen::VectorXd& mean() const { return mean_; }
  double trace() const { return trace_; }
  std::size_t passes() const { return passes_; }

 private:
  const PcaSpec& spec_;
  const RealizationGenerator& generate_;
  Eigen::VectorXd mean_;
  double trace_ = 0;
  std::size_t passes_ = 0;
};

}  // namespace

double PcaModes::retainedFraction() const { return totalVariance > 0 ? variances.sum() / totalVariance : 1.0; }

Eigen::VectorXd PcaModes::expand(std::span<const double> eta) const {
  require(eta.size() == size(), "PCA field: expected " + std::to_string(size()) + " standardized coordinates, got " +
                                    std::to_string(eta.size()));
  Eigen::VectorXd xi(variances.size());
  for (Eigen::Index k = 0; k < xi.size(); ++k) {
    require(std::isfinite(eta[static_cast<std::size_t>(k)]), "PCA field: coordinate " + std::to_string(k) + " is not finite");
    xi[k] = std::sqrt(variances[k]) * eta[static_cast<std::size_t>(k)];
  }
  return mean + modes * xi;  // 000:(5.4)
}

PcaModes streamedPca(const PcaSpec& spec, const RealizationGenerator& generate) {
  require(spec.values > 0, "streamed PCA: realizations must hold at least one value");
  require(spec.realizations >= 2, "streamed PCA: the sample covariance needs at least 2 realizations, got " +
                                      std::to_string(spec.realizations));
  require(spec.modes >= 1 && spec.modes <= spec.values, "streamed PCA: modes must lie in [1, " +
                                                            std::to_string(spec.values) + "], got " +
                                                            std::to_string(spec.modes));
  require(static_cast<bool>(generate), "streamed PCA: no realization generator given");

  StreamedCovariance covariance(spec, generate);
  const BlockProduct apply = [&covariance](const Eigen::MatrixXd& X, Eigen::MatrixXd& CX) { covariance.apply(X, CX); };
  EigenPairs pairs = randomizedEigen(spec.values, apply, {spec.modes, spec.oversampling, spec.powerIterations, spec.seed});
  PcaModes out;
  out.mean = covariance.mean();
  out.modes = std::move(pairs.vectors);
  out.variances = pairs.values.cwiseMax(0.0);  // C is PSD: negative round-off means zero
  out.totalVariance = covariance.trace();
  out.realizations = spec.realizations;
  out.passes = covariance.passes();
  return out;
}

}  // namespace peristep
