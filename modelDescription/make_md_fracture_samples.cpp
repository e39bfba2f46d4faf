// Writes the FMU's resources/md_fracture_samples.bin for scene learnedFracture: the LPS model learned from
// the static MD sets (the project's model, K >= 0, kLearnedDelta and kLearnedOrder: the fit of
// bench/learn_predict), its s0 learned on frames 5-20 of sample III (learning/prediction_window_loss.hpp) and
// the frames of the three fracture samples, from the committed coarse-grained data (HDF5, which the FMU does
// not read).
//   make_md_fracture_samples data/learning/graphene_md.h5 resources/md_fracture_samples.bin
#include <cstdio>
#include <exception>

#include "learning/data_sets.hpp"
#include "learning/kernel_fit.hpp"
#include "learning/lattice_stencil.hpp"
#include "learning/md_fracture_samples.hpp"
#include "learning/prediction_window_loss.hpp"

using namespace peristep::learning;

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: make_md_fracture_samples <coarse-grained data.h5> <out.bin>\n");
    return 2;
  }
  try {
    const CoarseDataFile file = readCoarseData(argv[1]);
    const StaticData train = staticData(file.sets.at("train"));
    StaticResidual res(train.lattice, makeLatticeStencil(train.lattice.hx, train.lattice.hy, kLearnedDelta),
                       kLearnedOrder, train.samples, train.weight);
    const KernelFit fit = fitKernel(res, {.nonnegative = true});
    MdFractureData data;
    data.model = {fit.kernel, fit.lambda, fit.mu, train.lattice.hx};
    for (const MdFractureSample& s : kMdFractureSamples) {
      const CoarseDataSet& set = file.sets.at(s.set);
      data.samples.push_back(fractureFrames(set));
      data.intervalSeconds.push_back(set.frameInterval);
    }
    data.model.s0 = learnCriticalStretch(data.samples.front(), kMdFractureSamples.front(), data.model).s0;
    writeMdFractureData(argv[2], data);
    std::printf("wrote %s: kernel alpha = %.4f, lambda = %.4f, mu = %.4f eV/A^3, s0 = %.4f, %zu samples\n",
                argv[2], fit.kernel.alpha, fit.lambda, fit.mu, data.model.s0, data.samples.size());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "make_md_fracture_samples: %s\n", e.what());
    return 1;
  }
  return 0;
}
