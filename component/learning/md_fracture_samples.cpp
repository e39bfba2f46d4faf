#include "learning/md_fracture_samples.hpp"

#include <cmath>
#include <fstream>
#include <iterator>

#include "core/byte_stream.hpp"
#include "core/errors.hpp"
#include "learning/lattice_stencil.hpp"

namespace peristep::learning {

namespace {

constexpr double kHalfSide = 50.0;  // the MD sheet is [-50, 50]^2 A, the slit x1 = 0, x2 from -50 to -25 A
constexpr char kMagic[] = "PeriStep MD fracture samples 3";

}  // namespace

double predictionHorizon(const CoarseGrid& grid, const LearnedModel& model, const PredictionVariant& v) {
  return model.kernel.delta * grid.hx / (v.referenceSpacing > 0 ? v.referenceSpacing : model.trainingSpacing);
}

DamagedLpsOperator predictionOperator(const CoarseGrid& grid, const LearnedModel& model, const PredictionVariant& v) {
  const double delta = predictionHorizon(grid, model, v);
  const BernsteinKernel kernel{delta, model.kernel.alpha, model.kernel.D};  // K/m only: the scale does not matter
  DamagedLpsOperator op(grid, makeLatticeStencil(grid.hx, grid.hy, delta), kernel, model.lambda, model.mu);
  op.setFreeSurfaceTerms(v.freeSurface);
  op.setCorrectedDilatation(v.correctedDilatation);
  return op;
}

PredictionCase predictionCase(const CoarseGrid& grid, const MdFractureSample& sample, const LearnedModel& model,
                              double s0AtH5, std::size_t substeps, const PredictionVariant& v) {
  const double delta = predictionHorizon(grid, model, v);
  PredictionCase c{predictionOperator(grid, model, v), {}};
  c.setup.s0 = s0AtH5 * sample.s0Scale;
  c.setup.substeps = substeps;
  // The slit just right of x1 = 0: on the fine grid a lattice column lies on x1 = 0.
  c.setup.initialStretch = c.op.slit(1e-6, -kHalfSide - 10, 1e-6, -25);
  for (std::size_t p = 0; p < grid.size(); ++p)
    c.setup.prescribed.push_back(sample.edgesDriven && std::abs(grid.x(p)) > kHalfSide - v.layer * delta);
  return c;
}

void writeMdFractureData(const std::string& path, const MdFractureData& d) {
  ByteWriter w;
  w.putArray(std::vector<char>(std::begin(kMagic), std::end(kMagic)));
  w.put(d.model.kernel.delta);
  w.put(d.model.kernel.alpha);
  w.putArray(d.model.kernel.D);
  w.put(d.model.lambda);
  w.put(d.model.mu);
  w.put(d.model.trainingSpacing);
  w.put(d.model.s0);
  w.put<std::uint64_t>(d.samples.size());
  for (std::size_t k = 0; k < d.samples.size(); ++k) {
    const FractureFrames& f = d.samples[k];
    w.put<std::uint64_t>(f.grid.nx);
    w.put<std::uint64_t>(f.grid.ny);
    for (const double v : {f.grid.x0, f.grid.y0, f.grid.hx, f.grid.hy, f.interval, d.intervalSeconds[k]}) w.put(v);
    w.putArray(f.rho);
    w.put<std::uint64_t>(f.u.size());
    for (std::size_t i = 0; i < f.u.size(); ++i) {
      w.putArray(f.u[i]);
      w.putArray(f.b[i]);
    }
  }
  const std::vector<std::uint8_t> bytes = w.take();
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  require(static_cast<bool>(out), "cannot write " + path);
}

MdFractureData readMdFractureData(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  require(static_cast<bool>(in), "cannot read the MD fracture samples " + path);
  const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  try {
    ByteReader r(bytes);
    require(r.getArray<char>() == std::vector<char>(std::begin(kMagic), std::end(kMagic)), "not its format");
    MdFractureData d;
    d.model.kernel.delta = r.get<double>();
    d.model.kernel.alpha = r.get<double>();
    d.model.kernel.D = r.getArray<double>();
    d.model.lambda = r.get<double>();
    d.model.mu = r.get<double>();
    d.model.trainingSpacing = r.get<double>();
    d.model.s0 = r.get<double>();
    const auto samples = r.get<std::uint64_t>();
    for (std::uint64_t k = 0; k < samples; ++k) {
      FractureFrames f;
      f.grid.nx = r.get<std::uint64_t>();
      f.grid.ny = r.get<std::uint64_t>();
      f.grid.x0 = r.get<double>(), f.grid.y0 = r.get<double>(), f.grid.hx = r.get<double>(), f.grid.hy = r.get<double>();
      f.interval = r.get<double>();
      d.intervalSeconds.push_back(r.get<double>());
      f.rho = r.getArray<double>(f.grid.size());
      const auto frames = r.get<std::uint64_t>();
      for (std::uint64_t i = 0; i < frames; ++i) {
        f.u.push_back(r.getArray<double>(2 * f.grid.size()));
        f.b.push_back(r.getArray<double>(2 * f.grid.size()));
      }
      d.samples.push_back(std::move(f));
    }
    r.expectEnd();
    require(d.samples.size() == kMdFractureSamples.size(), "wrong number of samples");
    return d;
  } catch (const std::exception& e) {
    throw InvalidInput("the MD fracture samples " + path + " are damaged: " + e.what());
  }
}

}  // namespace peristep::learning
