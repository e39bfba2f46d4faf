#pragma once
// The picture `peristep run` leaves for a bar (the gamutBar scene, which has nothing on the plate
// grid): the stress-strain path of the bar's end over the steps, barStress against barStrain, with
// the cyclic Ramberg-Osgood fit n', K' in the legend once the run has computed it.
#include <filesystem>
#include <string>
#include <vector>

#include "result_layout.hpp"

namespace peristep::host {

// True when the run's outputs include a bar's stress and strain that change during the run.
bool isBarRun(const ResultLayout& layout, const std::vector<StepScalars>& history);

// Returns "" or why nothing was drawn.
std::string writeStressStrainPicture(const std::filesystem::path& png, const ResultLayout& layout,
                                     const std::vector<StepScalars>& history, const std::string& title);

}  // namespace peristep::host
