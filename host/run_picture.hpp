#pragma once
// The picture `peristep run` leaves next to its results (<name>.png), drawn by gnuplot from the last
// finished step: a title (scene; step, time and the ramped quantity), axes in the length unit that
// suits the domain (m, mm, µm, nm), and a colour bar with the field's name and unit.
//  - Damage somewhere (cracks, pre-cracks): the material phases in damage_picture's colours with a
//    legend of their moduli (named glass and crystal for the glass-ceramic), Void (holes) left empty
//    and out of the legend, and the cracks (damage >= kCrackDamage) over the material, coloured by
//    damage on the colour bar.
//  - No damage (the smooth scenes): the displacement magnitude |u| with the grid deformed by u,
//    magnified by the factor given in the legend.
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "png_writer.hpp"
#include "result_layout.hpp"

namespace peristep::host {

struct PictureCaption {
  std::string scene;            // first title line
  std::uint64_t step = 0, steps = 0;  // step is 1-based
  std::string inputUnit;        // unit of layout.inputName
};

struct PictureSize {
  unsigned width = 0, height = 0;
};
// 1000 px wide, as tall as the domain's aspect ratio needs (between 400 and 1300 px).
PictureSize runPictureSize(const ResultLayout& layout);

// The legend of the material: one entry per phase (colour, "glass, E = 80 GPa"; a phase whose points
// differ gives its range), none for Void; an empty modulus (the model has none) is "material".
std::vector<std::pair<Rgb, std::string>> phaseLegend(const ResultLayout& layout, const std::vector<double>& youngsModulus);

// Returns "" or why nothing was drawn (no coordinates or displacement on the grid, gnuplot failed).
std::string writeRunPicture(const std::filesystem::path& png, const ResultLayout& layout, const StepValues& step,
                            const PictureCaption& caption);

}  // namespace peristep::host
