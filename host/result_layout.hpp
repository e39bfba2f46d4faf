#pragma once
// What a run records, independent of where it is written: the grid, the constant parameters and the
// per-step outputs. The simulation fills it from the model description and the instance; the HDF5
// and XDMF writers only read it.
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

namespace peristep::host {

inline std::uint64_t elementCount(const std::vector<std::uint64_t>& shape) {
  std::uint64_t n = 1;
  for (std::uint64_t e : shape) n *= e;
  return n;
}

struct Attribute {
  std::string name;
  std::variant<std::vector<double>, std::vector<std::int64_t>, std::vector<std::uint64_t>, std::string> value;
};

// A named array with its FMI shape ([ny][nx] for fields on the grid), unit and description.
struct ArrayInfo {
  std::string name;
  std::vector<std::uint64_t> shape;
  std::string unit, description;
};

struct ResultLayout {
  std::uint64_t ny = 0, nx = 0;                // grid shape, image order [ny][nx]
  std::vector<ArrayInfo> constantArrays;       // parameter arrays (x, y, ...): written once
  std::vector<std::vector<double>> constantValues;
  std::vector<ArrayInfo> scalars;              // scalar outputs: one time series each
  std::vector<ArrayInfo> fields;               // array outputs: one [steps][shape...] dataset each
  std::string inputName;                       // the ramped input, empty when none
  std::vector<Attribute> fileAttributes;       // model name, FMU, scene, loading
  std::vector<Attribute> parameterAttributes;  // every scalar or small parameter, as used by the run

  bool onGrid(const ArrayInfo& a) const { return a.shape.size() == 2 && a.shape[0] == ny && a.shape[1] == nx; }
};

// What ParaView's XDMF readers are pointed at: HDF5 virtual datasets that map into the arrays above and
// hold no data of their own. Neither of ParaView 5.11's readers can select one step of a
// [steps][ny][nx] dataset (XDMF 2 applies its own extent selection on top of a HyperSlab item; XDMF 3
// leaves the HyperSlab's type unset and skips the array), and XDMF 3 reads no X_Y geometry; a plain
// dataset per step and an interleaved [ny][nx][2] geometry work with both.
inline std::string xdmfGeometryPath() { return "/xdmf/xy"; }
inline std::string xdmfFieldPath(std::uint64_t step, const std::string& name) {
  return "/xdmf/step_" + std::to_string(step + 1) + "/" + name;  // step 0 is the first one recorded
}

// The scalar part of one step: what the XDMF file holds inline and the history plot draws.
struct StepScalars {
  double time = 0, input = 0;
  std::vector<double> scalars;
};

// Values recorded after one fmi3DoStep, in the order of ResultLayout::scalars and ::fields.
struct StepValues {
  double time = 0;   // communication point reached by the step
  double input = 0;  // value of the ramped input during the step
  std::vector<double> scalars;
  std::vector<std::vector<double>> fields;
};

}  // namespace peristep::host
