// Prediction step of 003 (Sec. 5.2-5.4): the learned LPS model (kernel and moduli fitted here on the static
// sets; by default the project's model, K >= 0 with delta = 10 A, P = 2, the choice of learn_lps
// --nonnegative-kernel; s0 learned on frames 5-20 of sample III as learn_lps does, unless --s0 gives it) runs
// the coarse-grained fracture samples forward from frame 0 and is compared with the MD frames: relative
// displacement and damage errors over 40 frames.
//   learn_predict [--data data/learning/graphene_md.h5] [--s0 0.11] [--substeps 8] [--layer 1]
//                 [--scan 0.05,0.08,0.11,0.15,0.2] [--increments] [--diagnose] [--per-frame]
//                 [--signed-kernel --delta 20 --order 4] [--paper-horizon] [--corrected-dilatation] [--free-surface]
// Samples: III (training, h = 5 A; vertical edges prescribed), IV (test, h = 5 A; free edges, body force),
// III on h = 3.17 A with s0 sqrt(5/3.17) (003 Sec. 5.4); delta/h is the same on every grid.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "bench_cli.hpp"
#include "learning/data_sets.hpp"
#include "learning/fracture_prediction.hpp"
#include "learning/kernel_fit.hpp"
#include "learning/lps_symbol.hpp"
#include "learning/md_fracture_samples.hpp"
#include "learning/prediction_window_loss.hpp"

using namespace peristep::learning;

namespace {

constexpr double kNoDamage = 1e3;  // s0: only the slit's bonds (stretch +infinity) are broken

double seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

struct Outcome {
  PredictionError error;
  double netForce = 0, rmsForce = 0, rmsInertia = 0;  // frame 1 of the data: see balance()
  double wall = 0, s0 = 0;
  double rmsLast = 0;  // rms over the points of |u_MD| at the last frame [A]
  std::size_t prescribed = 0, points = 0;
  bool finite = true;
};

// How far the data are from the model's equation at frame 1 (before damage grows), over the free points:
// the mean of L_KN[u] (a net force: the corrected operator 003:(30) does not conserve momentum, so its mean
// need not vanish), its rms and the rms of rho u'' from the frames (003:(21)).
void balance(const DamagedLpsOperator& op, const FractureFrames& data, const PredictionSetup& s, Outcome& out) {
  std::vector<double> smax = s.initialStretch;
  op.updateMaxStretch(data.u[0], smax);
  op.updateMaxStretch(data.u[1], smax);
  const std::vector<double> L = op.apply(data.u[1], smax, s.s0);
  const double dt2 = data.interval * data.interval;
  double mean[2] = {0, 0}, ll = 0, aa = 0, n = 0;
  for (std::size_t p = 0; p < data.rho.size(); ++p) {
    if (s.prescribed[p]) continue;
    n += 1;
    for (std::size_t c = 0; c < 2; ++c) {
      const std::size_t i = 2 * p + c;
      const double a = data.rho[p] * (data.u[2][i] - 2 * data.u[1][i] + data.u[0][i]) / dt2;
      mean[c] += L[i], ll += L[i] * L[i], aa += a * a;
    }
  }
  out.netForce = std::hypot(mean[0], mean[1]) / n, out.rmsForce = std::sqrt(ll / n), out.rmsInertia = std::sqrt(aa / n);
}

constexpr double kHalfSide = 50.0;  // the MD sheet is [-50, 50]^2 A, the slit x1 = 0, x2 from -50 to -25 A

// --diagnose (sample III): is frame 0 an equilibrium of the learned model? Strains of frame 0 (least-squares
// slopes of u1 in x1, u2 in x2 over the free points with |x1| > 12 A, away from the slit), the model's
// traction-free lateral strain for that stretch (plane stress: sigma22 = 0 -> e22 = -lambda/(lambda+2mu) e11),
// the force L_KN of both linear fields and how far the model moves them in 40 frames from rest with the edge
// layers held and no damage, without and with the slit (broken from the start); the same from MD frame 0.
void diagnose(const DamagedLpsOperator& op, const FractureFrames& data, const PredictionSetup& s, const LearnedModel& fit,
              double delta) {
  const CoarseGrid& g = op.grid();
  double n = 0, sx = 0, sxx = 0, sxu = 0, su = 0, sy = 0, syy = 0, syv = 0, sv = 0;
  for (std::size_t p = 0; p < g.size(); ++p) {
    if (s.prescribed[p] || std::abs(g.x(p)) < 12) continue;
    const double x = g.x(p), y = g.y(p), ux = data.u[0][2 * p], uy = data.u[0][2 * p + 1];
    n += 1, sx += x, sxx += x * x, sxu += x * ux, su += ux, sy += y, syy += y * y, syv += y * uy, sv += uy;
  }
  const double e11 = (n * sxu - sx * su) / (n * sxx - sx * sx), e22 = (n * syv - sy * sv) / (n * syy - sy * sy);
  const double e22Model = -fit.lambda / (fit.lambda + 2 * fit.mu) * e11;
  std::printf("    frame 0: e11 = %.4f, e22 = %.4f; the model's traction-free e22 = %.4f\n", e11, e22, e22Model);
  // rms of L_KN,2 in the top and bottom delta layers and inside, largest |u - u0| after 40 frames and where.
  const auto report = [&](const char* what, const std::vector<double>& u0, const std::vector<double>& slit) {
    std::vector<double> smax = slit;
    op.updateMaxStretch(u0, smax);
    const std::vector<double> L = op.apply(u0, smax, kNoDamage);
    double layer = 0, nl = 0, inside = 0, ni = 0;
    for (std::size_t p = 0; p < g.size(); ++p) {
      if (s.prescribed[p]) continue;
      const double l2 = L[2 * p + 1] * L[2 * p + 1];
      if (std::abs(g.y(p)) > kHalfSide - delta) layer += l2, nl += 1; else inside += l2, ni += 1;
    }
    FractureDrive d;
    d.rho = data.rho, d.prescribed = s.prescribed, d.u0 = u0, d.u1 = u0, d.initialStretch = slit;
    d.boundary = [&](double, std::vector<double>& v) { v = u0; };
    const FractureRun r = runFracture(op, d, kNoDamage, data.interval / 8, 40 * 8, 40 * 8);
    std::size_t km = 0;
    for (std::size_t k = 0; k < u0.size(); ++k)
      if (std::abs(r.u.back()[k] - u0[k]) > std::abs(r.u.back()[km] - u0[km])) km = k;
    std::printf("    %-34s %-8s rms L_KN,2 %.2e (top/bottom layers) %.2e (inside); held at rest 40 frames: "
                "largest |u - u0| %.3g A (u%zu at (%.1f, %.1f))\n",
                what, slit.empty() ? "no slit" : "slit", std::sqrt(layer / nl), std::sqrt(inside / ni),
                std::abs(r.u.back()[km] - u0[km]), km % 2 + 1, g.x(km / 2), g.y(km / 2));
  };
  for (const std::vector<double>& slit : {std::vector<double>{}, s.initialStretch}) {
    for (const double e : {e22, e22Model}) {
      std::vector<double> u(2 * g.size());
      for (std::size_t p = 0; p < g.size(); ++p) u[2 * p] = e11 * g.x(p), u[2 * p + 1] = e * g.y(p);
      char what[64];
      std::snprintf(what, sizeof what, "u = (%.4f x1, %.4f x2)", e11, e);
      report(what, u, slit);
    }
    report("MD frame 0", data.u[0], slit);
  }
}

// Is the learned operator on this stencil still the elastic operator it was fitted as? Its Fourier symbol at
// long waves (1000 A; Navier: S11/k^2 = lambda + 2 mu, S22/k^2 = mu along x1) and its smallest eigenvalue over
// the wave vectors of a 200 x 200 periodic lattice of the same spacing (negative: a mode grows).
void describeStencil(const char* what, const LatticeStencil& st, const BernsteinKernel& kernel, double lambda,
                     double mu) {
  const double k = 2 * M_PI / 1000;
  const Symbol S = lpsSymbol(st, kernel, lambda, mu, k, 0.0);
  const Solvability sv = checkSolvability(PeriodicLattice{200, 200, st.hx, st.hy}, st, kernel, lambda, mu);
  std::printf("    stencil %-22s h = %.3f x %.3f A, delta = %.3f A, %zu bonds: long waves along x1 S11/k^2 %.3f "
              "(lambda + 2 mu %.3f), S22/k^2 %.3f (mu %.3f) eV/A^3; smallest symbol eigenvalue %.2e (%s)\n",
              what, st.hx, st.hy, st.delta, st.size(), S[0] / (k * k), lambda + 2 * mu, S[2] / (k * k), mu,
              sv.minEigen, sv.minEigen > 0 ? "positive" : "NOT positive");
}

// Growth of the prediction's linear modes on the bounded sample, bond states fixed (intact, or the slit broken):
// rho u'' = -L u over the free points, modes e^{s t} with s^2 = -(eigenvalue of rho^-1 L); printed per frame.
void modeGrowth(const DamagedLpsOperator& op, const FractureFrames& data, const PredictionSetup& s, bool slit) {
  const CoarseGrid& g = op.grid();
  std::vector<std::size_t> free;
  for (std::size_t p = 0; p < g.size(); ++p)
    if (!s.prescribed[p]) free.push_back(2 * p), free.push_back(2 * p + 1);
  const std::size_t n = free.size();
  std::vector<double> smax = slit ? s.initialStretch : std::vector<double>{}, u(2 * g.size(), 0.0);
  op.updateMaxStretch(u, smax);
  Eigen::MatrixXd A(n, n);
  for (std::size_t j = 0; j < n; ++j) {
    u.assign(u.size(), 0.0);
    u[free[j]] = 1.0;
    const std::vector<double> L = op.apply(u, smax, kNoDamage);
    for (std::size_t i = 0; i < n; ++i) A(i, j) = L[free[i]] / data.rho[free[i] / 2];
  }
  const Eigen::VectorXcd e = Eigen::EigenSolver<Eigen::MatrixXd>(A, false).eigenvalues();
  double fastest = 0;
  std::size_t growing = 0;
  for (const std::complex<double> l : e) {
    const double perFrame = std::sqrt(-l).real() * data.interval;
    fastest = std::max(fastest, perFrame);
    if (perFrame > 1e-3) ++growing;
  }
  std::printf("    linear modes, %-8s %zu of %zu grow faster than e^0.001 per frame; the fastest by e^%.3f per frame "
              "(x %.3g over 40 frames)\n", slit ? "slit:" : "intact:", growing, n, fastest, std::exp(40 * fastest));
}

// increments: the frames minus frame 0, i.e. frame 0 taken as the unstressed reference state (sample III
// is pre-stretched by 10% in MD, a state 003's sample is not in and the learned linear model is not made for).
Outcome predict(const CoarseDataSet& set, const MdFractureSample& smp, const LearnedModel& model, double s0,
                std::size_t substeps, bool increments, const PredictionVariant& variant, bool diagnostics = false) {
  const auto t0 = std::chrono::steady_clock::now();
  FractureFrames data = fractureFrames(set);
  if (increments) subtractFrame0(data);
  const PredictionCase pc = predictionCase(set.grid, smp, model, s0, substeps, variant);
  const DamagedLpsOperator& op = pc.op;
  const PredictionSetup& s = pc.setup;
  const double delta = predictionHorizon(set.grid, model, variant);
  Outcome out;
  out.s0 = s.s0;
  out.points = set.grid.size();
  for (const char c : s.prescribed) out.prescribed += c ? 1 : 0;
  balance(op, data, s, out);
  for (const double v : data.u[s.lastFrame]) out.rmsLast += v * v;
  out.rmsLast = std::sqrt(out.rmsLast / static_cast<double>(set.grid.size()));
  if (diagnostics) {
    const BernsteinKernel kernel{delta, model.kernel.alpha, model.kernel.D};
    describeStencil("of this grid:", makeLatticeStencil(set.grid.hx, set.grid.hy, delta), kernel, model.lambda,
                    model.mu);
    modeGrowth(op, data, s, false);
    modeGrowth(op, data, s, true);
  }
  if (diagnostics && smp.edgesDriven) diagnose(op, data, s, model, delta);
  const FractureRun run = predictFracture(op, data, s);
  out.finite = run.finite;
  if (run.finite) out.error = predictionError(op, data, run, s);
  out.wall = seconds(t0);
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Predict the MD fracture samples with the learned LPS model of 003 and print the errors"};
  std::string path = "data/learning/graphene_md.h5";
  double delta = kLearnedDelta, s0 = 0;
  PredictionVariant variant;
  int order = kLearnedOrder;
  std::size_t substeps = 8;
  std::vector<double> scan;
  bool increments = false, diagnostics = false, perFrame = false, paperHorizon = false, signedKernel = false;
  app.add_option("--data", path, "HDF5 file of learn_coarse_grain");
  app.add_option("--delta", delta, "horizon of the learned kernel [A] (learn_lps --nonnegative-kernel's choice: 10; 003: 20)");
  app.add_option("--order", order, "Bernstein order P (learn_lps --nonnegative-kernel's choice: 2; learn_lps's: 4)");
  app.add_option("--s0", s0, "critical stretch at h = 5 A (003: 0.11; default: learned on frames 5-20 of III)");
  app.add_option("--substeps", substeps, "explicit steps per MD frame interval");
  app.add_option("--layer", variant.layer, "width of the prescribed edge layers of sample III, in delta");
  app.add_flag("--increments", increments, "predict u - u(frame 0): frame 0 as the unstressed reference state");
  app.add_flag("--free-surface", variant.freeSurface, "with the free-surface sums of 003:(30)");
  app.add_flag("--corrected-dilatation", variant.correctedDilatation,
               "003's corrected dilatation (31)-(32) instead of theta of 003:(15) with the full neighbourhood's m");
  app.add_flag("--per-frame", perFrame, "also the displacement error of every 5th frame");
  app.add_flag("--diagnose", diagnostics,
               "is the model on each grid's stencil stable, and (III) is frame 0 an equilibrium of it?");
  app.add_flag("--paper-horizon", paperHorizon,
               "delta/h = delta / 5 A on every grid (003) instead of delta / h of the training lattice (its bonds)");
  app.add_flag("--signed-kernel", signedKernel, "003's kernel: D_k of either sign (else every D_k >= 0, K >= 0)");
  app.add_option("--scan", scan, "also: errors on sample III for these s0")->delimiter(',');
  if (const auto code = peristep::bench::parseArguments(app, argc, argv)) return *code;
  variant.referenceSpacing = paperHorizon ? kPaperSpacing : 0.0;
  try {
    const auto t0 = std::chrono::steady_clock::now();
    const CoarseDataFile file = readCoarseData(path);
    const StaticData train = staticData(file.sets.at("train"));
    StaticResidual res(train.lattice, makeLatticeStencil(train.lattice.hx, train.lattice.hy, delta), order,
                       train.samples, train.weight);
    const KernelFit fit = fitKernel(res, {.nonnegative = !signedKernel});
    const LearnedModel model{fit.kernel, fit.lambda, fit.mu, train.lattice.hx};
    std::printf("kernel fit (static training set, delta = %.1f A, P = %d): alpha = %.4f, lambda = %.4f TPa, "
                "mu = %.4f TPa, relative residual %.4f, %.1f s\n  D =",
                delta, order, fit.kernel.alpha, fit.lambda * kTPaPerEvA3, fit.mu * kTPaPerEvA3, fit.relativeResidual,
                seconds(t0));
    for (const double d : fit.kernel.D) std::printf(" %.5e", d);
    std::printf("\n");
    describeStencil("of the training lattice:", makeLatticeStencil(train.lattice.hx, train.lattice.hy, delta), fit.kernel,
                    fit.lambda, fit.mu);
    if (s0 <= 0) {  // the project's s0 step (learn_lps), with the prediction's operator
      const auto t1 = std::chrono::steady_clock::now();
      FractureFrames frames = fractureFrames(file.sets.at(kMdFractureSamples[0].set));
      if (increments) subtractFrame0(frames);
      const CriticalStretchFit learned =
          learnCriticalStretch(frames, kMdFractureSamples[0], model, 5, 20, substeps, variant);
      s0 = learned.s0;
      std::printf("s0 learned from the prediction error on frames 5-20 of III: %.4f, 95%% interval [%.4f, %.4f] "
                  "(%.1f s)\n", s0, learned.lower, learned.upper, seconds(t1));
    }
    const double interval = file.sets.at("fracture_train").frameInterval;
    std::printf("frame interval %.3e s, %zu steps per frame: dt = %.3e s; s0 = %.4f (at h = 5 A), eta = 0.05, "
                "edge layers of III %.2f delta%s%s\n\n",
                interval, substeps, interval / static_cast<double>(substeps), s0, variant.layer,
                increments ? "; displacements from frame 0 (--increments)" : "",
                paperHorizon ? "; delta/h = delta / 5 A (--paper-horizon)" : "");
    const auto run = [&](const MdFractureSample& smp, double s0Run, bool diagnose) {
      return predict(file.sets.at(smp.set), smp, model, s0Run, substeps, increments, variant, diagnose);
    };
    const auto& samples = kMdFractureSamples;
    std::printf("u, phi err: sqrt(sum_f |pred - MD|^2 / sum_f |MD|^2), frames 1-40; mean: of the per-frame ratios; "
                "u shift: u err without the mean of pred - MD per frame;\nphi 40: mean damage at frame 40, predicted / "
                "MD; frame 1 [eV/A^4]: |mean L_KN[u]|, rms L_KN[u], rms rho u'' of the MD frames over the free "
                "points\n");
    std::printf("%-26s %7s %11s %7s %7s %7s %7s %7s %11s %9s %8s %8s %8s %7s\n", "sample", "s0", "prescribed",
                "u err%", "phi%", "u mean%", "phi mn%", "u shift", "phi 40", "003 u/phi", "mean L", "rms L",
                "rms rho a", "wall s");
    const auto row = [perFrame](const char* name, const Outcome& o, const char* paper) {
      if (!o.finite) {
        std::printf("%-26s %7.4f %5zu/%-5zu  unstable (non-finite displacement)\n", name, o.s0, o.prescribed, o.points);
        return;
      }
      std::printf("%-26s %7.4f %5zu/%-5zu %7.1f %7.1f %7.1f %7.1f %7.1f %5.3f/%5.3f %9s %8.1e %8.1e %8.1e %7.2f\n",
                  name, o.s0, o.prescribed, o.points, 100 * o.error.displacement, 100 * o.error.damage,
                  100 * o.error.displacementMean, 100 * o.error.damageMean, 100 * o.error.displacementShifted,
                  o.error.lastDamage, o.error.lastDamageData, paper, o.netForce, o.rmsForce, o.rmsInertia, o.wall);
      if (perFrame) {
        std::printf("    u err %% at frames");
        for (std::size_t f = 5; f <= o.error.frameDisplacement.size(); f += 5)
          std::printf(" %zu: %.1f", f, 100 * o.error.frameDisplacement[f - 1]);
        std::printf("; rms |u_MD| at frame %zu: %.2f A\n", o.error.frameDisplacement.size(), o.rmsLast);
      }
      std::fflush(stdout);
    };
    for (const MdFractureSample& smp : samples) row(smp.name, run(smp, s0, diagnostics), smp.paper);
    if (!scan.empty()) {
      std::printf("\ns0 scan on sample III (h = 5 A); the data's damage uses the same s0, so only the "
                  "displacement error compares across s0:\n");
      double best = NAN, bestError = INFINITY;
      for (const double s : scan) {
        const Outcome o = run(samples[0], s, false);
        row(samples[0].name, o, samples[0].paper);
        if (o.finite && o.error.displacement < bestError) best = s, bestError = o.error.displacement;
      }
      std::printf("\nwith the s0 of the smallest displacement error on III, %.4f:\n", best);
      for (const MdFractureSample& smp : samples) row(smp.name, run(smp, best, false), smp.paper);
    }
    std::printf("\ntotal %.1f s\n", seconds(t0));
  } catch (const std::exception& e) {
    std::cerr << "learn_predict: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
