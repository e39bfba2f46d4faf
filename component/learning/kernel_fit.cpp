#include "learning/kernel_fit.hpp"

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"

namespace peristep::learning {

namespace {

struct Model {
  double alpha;
  std::vector<double> D;
};

// (beta_0..beta_{P-1}, alpha) -> alpha, D with D_k = xi_k / c_k(alpha) and xi as in kernel_fit.hpp: signed,
// xi_k = beta_k and xi_P = 1 - sum xi_k; nonnegative, xi_k = beta_k^2 / (1 + sum beta_j^2), xi_P = 1 / (...).
Model kernelModel(const StaticResidual& res, const Eigen::VectorXd& beta, bool nonnegative) {
  const int P = res.order();
  Model m{beta[P], {}};
  BernsteinKernel k{res.delta(), m.alpha, std::vector<double>(static_cast<std::size_t>(P) + 1, 0.0)};
  const double scale = nonnegative ? 1.0 / (1.0 + beta.head(P).squaredNorm()) : 1.0;
  double last = 1.0;
  for (int i = 0; i <= P; ++i) {
    double xi = last;
    if (nonnegative)
      xi = (i < P ? beta[i] * beta[i] : 1.0) * scale;
    else if (i < P)
      xi = beta[i], last -= xi;
    m.D.push_back(xi / k.weightedVolumeCoefficient(i));
  }
  return m;
}

// C(beta) and the least-squares (lambda, mu) for it.
struct Projection {
  Eigen::MatrixXd C;
  Eigen::Vector2d x;
  Eigen::VectorXd r;  // rhs - C x
};

Eigen::MatrixXd columnsOf(StaticResidual& res, const Model& m) {
  std::vector<double> c1, c2;
  res.columns(m.alpha, m.D, c1, c2);
  Eigen::MatrixXd C(static_cast<Eigen::Index>(res.rows()), 2);
  C.col(0) = Eigen::Map<const Eigen::VectorXd>(c1.data(), C.rows());
  C.col(1) = Eigen::Map<const Eigen::VectorXd>(c2.data(), C.rows());
  return C;
}

Projection project(StaticResidual& res, const Model& m) {
  Projection p;
  p.C = columnsOf(res, m);
  const Eigen::Map<const Eigen::VectorXd> b(res.rhs().data(), p.C.rows());
  p.x = p.C.colPivHouseholderQr().solve(b);
  p.r = b - p.C * p.x;
  return p;
}

double stepOf(double v) { return 1e-6 * std::max(1.0, std::abs(v)); }

// Levenberg-Marquardt on the projected residual over beta (variable projection: (lambda, mu) solved for each
// beta), from beta; on return beta is the minimizer and cur its projection. Counts into fit.
Projection minimizeProjected(StaticResidual& res, const KernelFitOptions& o, Eigen::VectorXd& beta, KernelFit& fit) {
  const Eigen::Index nb = beta.size(), P = nb - 1;
  const auto evaluate = [&](const Eigen::VectorXd& b) {
    ++fit.evaluations;
    return project(res, kernelModel(res, b, o.nonnegative));
  };
  Projection cur = evaluate(beta);
  double f = cur.r.squaredNorm(), damping = 1e-3;
  const auto admissible = [&](const Eigen::VectorXd& b) { return b[P] < 3.0; };  // 003:(37)
  for (fit.iterations = 0; fit.iterations < o.maxIterations; ++fit.iterations) {
    // Jacobian of the projected residual by central differences (exact VarPro derivative up to O(h^2)).
    Eigen::MatrixXd J(cur.r.size(), nb);
    for (Eigen::Index i = 0; i < nb; ++i) {
      Eigen::VectorXd bp = beta, bm = beta;
      const double h = stepOf(beta[i]);
      bp[i] += h;
      bm[i] -= h;
      J.col(i) = (evaluate(bp).r - evaluate(bm).r) / (2 * h);
    }
    const Eigen::MatrixXd JtJ = J.transpose() * J;
    const Eigen::VectorXd g = J.transpose() * cur.r;
    bool accepted = false;
    Eigen::VectorXd step;
    for (int tries = 0; tries < 40 && !accepted; ++tries) {
      Eigen::MatrixXd A = JtJ;
      for (Eigen::Index i = 0; i < nb; ++i) A(i, i) += damping * std::max(JtJ(i, i), 1e-300);
      step = A.ldlt().solve(-g);
      const Eigen::VectorXd trial = beta + step;
      Projection next = admissible(trial) ? evaluate(trial) : Projection{};
      const double fn = next.r.size() ? next.r.squaredNorm() : INFINITY;
      if (std::isfinite(fn) && fn <= f) {
        beta = trial;
        cur = std::move(next);
        f = fn;
        damping = std::max(damping / 10, 1e-12);
        accepted = true;
      } else {
        damping *= 10;
      }
    }
    // No descent even with heavy damping: stationary to round-off. Otherwise stop on a negligible step.
    if (!accepted || step.norm() <= o.stepTolerance * (beta.norm() + o.stepTolerance)) {
      fit.converged = true;
      break;
    }
  }
  return cur;
}

// The standard errors of lambda, mu, D_k and alpha at the minimizer: the covariance of theta = (lambda, mu,
// beta) from the full (unprojected) residual r = rhs - C(beta) (lambda, mu), carried to the reported
// quantities by the delta method.
void setStandardErrors(StaticResidual& res, bool nonnegative, const Eigen::VectorXd& beta, const Projection& cur,
                       KernelFit& fit) {
  const Eigen::Index nb = beta.size(), np = 2 + nb;
  const int P = static_cast<int>(nb) - 1;
  Eigen::MatrixXd J(cur.r.size(), np);
  J.col(0) = -cur.C.col(0);
  J.col(1) = -cur.C.col(1);
  for (Eigen::Index i = 0; i < nb; ++i) {
    Eigen::VectorXd bp = beta, bm = beta;
    const double h = stepOf(beta[i]);
    bp[i] += h;
    bm[i] -= h;
    J.col(2 + i) = -(columnsOf(res, kernelModel(res, bp, nonnegative)) - columnsOf(res, kernelModel(res, bm, nonnegative))) *
                   cur.x / (2 * h);
  }
  fit.sigma2 = fit.rss / static_cast<double>(std::max<Eigen::Index>(1, cur.r.size() - np));
  const Eigen::MatrixXd cov = fit.sigma2 * (J.transpose() * J).ldlt().solve(Eigen::MatrixXd::Identity(np, np));
  const auto reported = [&](const Eigen::VectorXd& theta) {  // q = (lambda, mu, D_0..D_P, alpha)
    const Model mm = kernelModel(res, theta.tail(nb), nonnegative);
    Eigen::VectorXd q(P + 4);
    q[0] = theta[0];
    q[1] = theta[1];
    for (int k = 0; k <= P; ++k) q[2 + k] = mm.D[static_cast<std::size_t>(k)];
    q[P + 3] = mm.alpha;
    return q;
  };
  Eigen::VectorXd theta(np);
  theta << cur.x, beta;
  Eigen::MatrixXd T(P + 4, np);
  for (Eigen::Index i = 0; i < np; ++i) {
    Eigen::VectorXd tp = theta, tm = theta;
    const double h = stepOf(theta[i]);
    tp[i] += h;
    tm[i] -= h;
    T.col(i) = (reported(tp) - reported(tm)) / (2 * h);
  }
  const Eigen::VectorXd var = (T * cov * T.transpose()).diagonal();
  fit.lambdaError = std::sqrt(var[0]);
  fit.muError = std::sqrt(var[1]);
  for (int k = 0; k <= P; ++k) fit.DError.push_back(std::sqrt(var[2 + k]));
  fit.alphaError = std::sqrt(var[P + 3]);
}

}  // namespace

KernelFit fitKernel(StaticResidual& res, const KernelFitOptions& o) {
  const int P = res.order();
  Eigen::VectorXd beta(P + 1);
  for (int i = 0; i < P; ++i) beta[i] = o.nonnegative ? 1.0 : 1.0 / (P + 1);  // all xi equal
  beta[P] = o.alpha0;
  KernelFit fit;
  const Projection cur = minimizeProjected(res, o, beta, fit);
  const Model m = kernelModel(res, beta, o.nonnegative);
  fit.kernel = BernsteinKernel{res.delta(), m.alpha, m.D};
  fit.lambda = cur.x[0];
  fit.mu = cur.x[1];
  fit.rss = cur.r.squaredNorm();
  const double bb = Eigen::Map<const Eigen::VectorXd>(res.rhs().data(), cur.r.size()).squaredNorm();
  fit.relativeResidual = std::sqrt(fit.rss / bb);
  setStandardErrors(res, o.nonnegative, beta, cur, fit);
  return fit;
}

double relativeResidual(StaticResidual& res, const BernsteinKernel& kernel, double lambda, double mu) {
  std::vector<double> c1, c2;
  res.columns(kernel.alpha, kernel.D, c1, c2);
  double rr = 0.0, bb = 0.0;
  for (std::size_t i = 0; i < res.rows(); ++i) {
    const double r = lambda * c1[i] + mu * c2[i] - res.rhs()[i];
    rr += r * r;
    bb += res.rhs()[i] * res.rhs()[i];
  }
  return std::sqrt(rr / bb);
}

}  // namespace peristep::learning
