#pragma once
// The plot of a sample study (`peristep sample`), drawn by gnuplot:
//  - the L2 errors of the mean and the standard deviation against the number of samples, log-log,
//    from the study's CSV: against the exact moments (errorMean, errorStd) where the component knows
//    them, against the study's last level (diffMean, diffStd) where that gives a curve (three levels
//    or more: one level has nothing to be compared with, two give one point);
//  - the distribution of each result the study is about (K_IC of a fracture scene, the outputs a scene
//    names in [output] results) over the last level's samples: a histogram, the mean and an interval
//    (Monte Carlo: the 95% interval of the mean; collocation: mean -+ std).
// One panel each, two to a row.
#include <filesystem>
#include <string>
#include <vector>

namespace peristep::host {

inline constexpr unsigned kSamplePlotWidth = 900, kSamplePlotHeight = 500;  // one panel

struct ResultDistribution {
  std::string name, unit;
  std::vector<double> values;  // the successful samples of the last level
  double mean = 0, std = 0;    // with the rule's weights
  double low = 0, high = 0;
  std::string interval;        // what [low, high] is, for the legend
};

// Width and height of a plot of `panels` panels.
unsigned samplePlotWidth(std::size_t panels);
unsigned samplePlotHeight(std::size_t panels);

// Writes <csv without extension>.png; returns the line to print: "wrote <png>" or why there is no plot.
std::string plotSampleStudy(const std::filesystem::path& csv, const std::string& title,
                            const std::vector<ResultDistribution>& results = {});

}  // namespace peristep::host
