// The learned LPS model of 003 predicting an MD fracture sample (scene learnedFracture): the model and the
// coarse-grained frames come from the FMU's resources (learning/md_fracture_samples.hpp); every
// communication step of a whole number of MD frame intervals runs the explicit steps of 003:(29) to the next
// frames (learning/fracture_forward.hpp) and adds them to the errors of 003 Sec. 5.1 against the MD frames.
// The run is bench/learn_predict's, step for step.
#include <cmath>
#include <map>
#include <mutex>

#include "core/byte_stream.hpp"
#include "core/errors.hpp"
#include "core/number_text.hpp"
#include "learning/md_fracture_samples.hpp"
#include "learning/model_units.hpp"
#include "scenes/scene_declaration.hpp"
#include "scenes/scene_runner.hpp"
#include "scenes/shared_variables.hpp"

namespace peristep {
namespace {

using namespace learning;

constexpr char kDataFile[] = "md_fracture_samples.bin";
constexpr std::size_t kStepsPerFrame = 8;  // bench/learn_predict's; the learned kernels' limit is ~1/4 frame

// Read once per process and path (a sample loop sets up many instances).
std::shared_ptr<const MdFractureData> sharedData(const std::string& resourcePath) {
  require(!resourcePath.empty(),
          "scene learnedFracture reads the MD frames from the FMU's resources, but the importer gave no "
          "resourcePath to fmi3InstantiateCoSimulation");
  static std::mutex mutex;
  static std::map<std::string, std::shared_ptr<const MdFractureData>> cache;
  const std::string path = resourcePath + (resourcePath.back() == '/' ? "" : "/") + kDataFile;
  const std::lock_guard lock(mutex);
  auto& entry = cache[path];
  if (!entry) entry = std::make_shared<const MdFractureData>(readMdFractureData(path));
  return entry;
}

PointCloud gridCloud(const CoarseGrid& g) {
  PointCloud c;
  c.nx = g.nx, c.ny = g.ny, c.h = g.hx;
  for (std::size_t p = 0; p < g.size(); ++p) {
    c.x.push_back(g.x(p) * 1e-10);  // [m]
    c.y.push_back(g.y(p) * 1e-10);
    c.image.push_back(static_cast<std::int64_t>(p));
    c.domain.push_back(p);
    c.region.push_back(Region::Domain);
  }
  return c;
}

class LearnedFractureRunner final : public Runner {
 public:
  explicit LearnedFractureRunner(const SceneParameters& p)
      : data_(sharedData(p.resourcePath)),
        index_(static_cast<std::size_t>(p.learnedSample)),
        frames_(data_->samples.at(index_)),
        case_(predictionCase(frames_.grid, kMdFractureSamples[index_], data_->model,
                             p.learnedCriticalStretch > 0 ? p.learnedCriticalStretch : data_->model.s0,
                             p.internalTimeStep > 0 ? stepsPerFrame(p.internalTimeStep) : kStepsPerFrame)),
        drive_(predictionDrive(frames_, case_.setup)),
        stepper_(case_.op, drive_, case_.setup.s0, frames_.interval / static_cast<double>(case_.setup.substeps)),
        errors_(case_.op, case_.setup, frames_.u.front()),
        cloud_(gridCloud(frames_.grid)) {
    const CoarseGrid& g = frames_.grid;
    require(p.grid.nx == g.nx && p.grid.ny == g.ny,
            std::string("sample ") + kMdFractureSamples[index_].name + " is on a " + std::to_string(g.nx) + " x " +
                std::to_string(g.ny) + " grid: set nx = " + std::to_string(g.nx) + ", ny = " + std::to_string(g.ny) +
                " (got " + std::to_string(p.grid.nx) + " x " + std::to_string(p.grid.ny) + ")");
  }

  const PointCloud& cloud() const override { return cloud_; }

  // Whole frame intervals only: the frames drive the edges and the body force, and the errors are per frame.
  void advance(const SceneInputs& in) override {
    const double interval = data_->intervalSeconds[index_], frames = in.stepSize / interval;
    const auto n = static_cast<std::size_t>(std::llround(frames));
    require(std::abs(frames - static_cast<double>(n)) < 1e-6,
            "scene learnedFracture steps whole MD frame intervals of " + numberText(interval) +
                " s; communicationStepSize = " + numberText(in.stepSize) + " s is not one");
    require(frame_ + n < frames_.u.size(), "sample " + std::string(kMdFractureSamples[index_].name) + " has " +
                                               std::to_string(frames_.u.size() - 1) + " frames; a step to frame " +
                                               std::to_string(frame_ + n) + " goes beyond them");
    for (std::size_t k = 0; k < n; ++k) {
      for (std::size_t s = 0; s < case_.setup.substeps; ++s)
        if (!stepper_.advance())
          throw SolverFailure("the learned model's run became unstable (non-finite displacement) at step " +
                              std::to_string(stepper_.step() + 1) + ": use a smaller internalTimeStep");
      ++frame_;
      errors_.add(stepper_.u(), stepper_.maxStretch(), frames_.u[frame_]);
    }
  }
  std::vector<double> ux() const override { return component(0); }
  std::vector<double> uy() const override { return component(1); }
  // The learned moduli as one Young's modulus, E = 4 mu (lambda + mu) / (lambda + 2 mu) of the 2D model
  // (thickness 3.35 A), everywhere.
  std::vector<double> youngsModulus() const override {
    const double l = data_->model.lambda, m = data_->model.mu;
    return std::vector<double>(cloud_.size(), 4 * m * (l + m) / (l + 2 * m) * kTPaPerEvA3 * 1e12);
  }
  std::vector<double> damage() const override { return case_.op.damage(stepper_.maxStretch(), case_.setup.s0); }
  double predictionErrorDisplacement() const { return errors_.displacement(); }
  double predictionErrorDamage() const { return errors_.damage(); }

  std::vector<std::uint8_t> saveState() const override {
    ByteWriter w;
    w.put<std::uint64_t>(frame_);
    w.putArray(stepper_.saveState());
    w.putArray(errors_.saveState());
    return w.take();
  }
  void restoreState(std::span<const std::uint8_t> bytes) override {
    ByteReader r(bytes);
    const auto frame = r.get<std::uint64_t>();
    const std::vector<std::uint8_t> stepper = r.getArray<std::uint8_t>(), errors = r.getArray<std::uint8_t>();
    r.expectEnd();
    stepper_.restoreState(stepper);
    errors_.restoreState(errors);
    frame_ = static_cast<std::size_t>(frame);
  }

 private:
  std::size_t stepsPerFrame(double internalTimeStep) const {
    return static_cast<std::size_t>(std::ceil(data_->intervalSeconds[index_] / internalTimeStep - 1e-9));
  }
  // A displacement component on the grid [m] (the model works in A).
  std::vector<double> component(std::size_t c) const {
    std::vector<double> v;
    for (std::size_t p = 0; p < cloud_.size(); ++p) v.push_back(stepper_.u()[2 * p + c] * 1e-10);
    return v;
  }

  std::shared_ptr<const MdFractureData> data_;
  std::size_t index_;
  const FractureFrames& frames_;
  PredictionCase case_;
  FractureDrive drive_;
  FractureStepper stepper_;
  PredictionErrorSums errors_;
  PointCloud cloud_;
  std::size_t frame_ = 0;
};

using namespace declaration_names;
constexpr ValueReference kSample = 140, kCriticalStretch = 141, kErrorDisplacement = 142, kErrorDamage = 143;

const LearnedFractureRunner& learned(const Runner& r) { return static_cast<const LearnedFractureRunner&>(r); }

// learnedSample's items 1, 2, 3 are LearnedSample 0, 1, 2 (the values are checked when they are set).
void configure(SceneParameters& p) {
  p.learnedSample = static_cast<LearnedSample>(static_cast<std::int32_t>(ownValue(p, kSample)) - 1);
  p.learnedCriticalStretch = ownValue(p, kCriticalStretch);
}

// The sample has its own grid (the runner checks nx, ny).
void validateLearned(const SceneParameters& p) {
  require(std::isfinite(p.learnedCriticalStretch) && p.learnedCriticalStretch >= 0 && std::isfinite(p.internalTimeStep) &&
              p.internalTimeStep >= 0,
          "learnedCriticalStretch and internalTimeStep must be >= 0 (got " + std::to_string(p.learnedCriticalStretch) +
              ", " + std::to_string(p.internalTimeStep) + ")");
}

}  // namespace

SceneDeclaration learnedFractureScene() {
  return {
      .id = SceneId::LearnedFracture,
      .name = "learnedFracture",
      .description =
          "The LPS model learned from molecular dynamics of graphene (You et al., paper 003) predicting an MD "
          "fracture sample (learnedSample) from its frame 0: the kernel, moduli and s0 learned by learn_lps (or s0 = "
          "learnedCriticalStretch), edges or body force driven by the frames; needs the FMU's resources. nx, ny: the "
          "sample's grid (20 x 20, or 31 x 31 for trainingFine); each communication step is a whole number of MD "
          "frame intervals of 4.95e-14 s (8 explicit steps each, or internalTimeStep), up to frame 40 (stop time "
          "1.98e-12 s); predictionErrorDisplacement and predictionErrorDamage compare with the frames so far",
      .variables = {
    {.name = "learnedSample", .vr = kSample, .type = T::Enumeration, .causality = C::Parameter,
     .variability = V::Fixed, .initial = I::Exact,
     .description = "learnedFracture scene: the MD fracture sample predicted", .declaredType = "PeriStep.LearnedSample",
     .start = "1"},
    {.name = "learnedCriticalStretch", .vr = kCriticalStretch, .type = T::Float64,
     .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
     .description = "learnedFracture scene: critical stretch s0 of the smooth bond states 003:(28) at h = 5 A "
                    "(the fine sample takes s0 sqrt(5/3.17), 003 Sec. 5.4); 0: the s0 learned with the model "
                    "(frames 5-20 of sample III); 003's value 0.11",
     .start = "0", .min = Bound{0}},
    {.name = "predictionErrorDisplacement", .vr = kErrorDisplacement, .type = T::Float64,
     .causality = C::Output, .variability = V::Continuous, .initial = I::Calculated,
     .description = "learnedFracture scene: sqrt(sum_f |u_pred - u_MD|^2 / sum_f |u_MD|^2) over the frames "
                    "predicted so far and all points (003 Sec. 5.1); 0 before the first frame and in the other "
                    "scenes",
     .dependencies = onNoInput(), .cName = "PREDICTION_ERROR_U"},
    {.name = "predictionErrorDamage", .vr = kErrorDamage, .type = T::Float64,
     .causality = C::Output, .variability = V::Continuous, .initial = I::Calculated,
     .description = "learnedFracture scene: the same for the damage 003:(46), the MD frames' own with the same "
                    "s0 and slit; 0 before the first frame and in the other scenes",
     .dependencies = onNoInput()},
      },
      .enumerations = {
    {"PeriStep.LearnedSample",
     "MD fracture samples of paper 003 Sec. 5 (scripts/md/generate.py)",
     {{"training", 1,
       "Sample III, h = 5 A (nx = ny = 20): pre-stretched sheet with a slit, vertical edges pulled; the edge "
       "layers one horizon wide follow the frames"},
      {"test", 2, "Sample IV, h = 5 A (nx = ny = 20): free edges, the body-force pulse"},
      {"trainingFine", 3,
       "Sample III on h = 3.17 A (nx = ny = 31), horizon 4 h, s0 scaled by sqrt(5/3.17)"}},
     "PERISTEP_LEARNED_"},
      },
      .outputs = {{kErrorDisplacement, [](const Runner& r) { return learned(r).predictionErrorDisplacement(); }},
                  {kErrorDamage, [](const Runner& r) { return learned(r).predictionErrorDamage(); }}},
      .configure = configure,
      .validate = validateLearned,
      .make = [](const SceneParameters& p) -> std::unique_ptr<Runner> {
        return std::make_unique<LearnedFractureRunner>(p);
      },
  };
}

}  // namespace peristep
