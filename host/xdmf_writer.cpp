#include "xdmf_writer.hpp"

#include <cstdio>
#include <sstream>

#include "atomic_file.hpp"
#include "exact_text.hpp"
#include "host_errors.hpp"

namespace peristep::host {

namespace {

std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string dims(const std::vector<std::uint64_t>& shape) {
  std::string out;
  for (std::uint64_t e : shape) {
    if (!out.empty()) out += ' ';
    out += std::to_string(e);
  }
  return out;
}


// An HDF5 dataset of doubles, `h5` being "<file>:".
std::string hdfItem(const std::string& h5, const std::string& path, const std::string& dimensions) {
  return "<DataItem Dimensions=\"" + dimensions + "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" + h5 +
         escape(path) + "</DataItem>";
}

// One value written in the document itself, exactly.
std::string xmlItem(double value) {
  return "<DataItem Dimensions=\"1\" NumberType=\"Float\" Precision=\"8\" Format=\"XML\">" + exactText(value) +
         "</DataItem>";
}

void attribute(std::ostream& out, const std::string& name, const char* center, const std::string& item) {
  out << "        <Attribute Name=\"" << escape(name) << "\" AttributeType=\"Scalar\" Center=\"" << center << "\">" << item
      << "</Attribute>\n";
}

// The temporal collection around the grids, and one grid's time, topology and geometry: the same for a
// run's steps and a study's levels.
void openCollection(std::ostream& out, const std::string& name) {
  out << "<?xml version=\"1.0\" ?>\n"
      << "<Xdmf Version=\"3.0\">\n"
      << "  <Domain>\n"
      << "    <Grid Name=\"" << name << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
}

void closeCollection(std::ostream& out) {
  out << "    </Grid>\n"
      << "  </Domain>\n"
      << "</Xdmf>\n";
}

void openGrid(std::ostream& out, const std::string& name, const std::string& time, const std::string& h5,
              const std::string& gridDims) {
  const std::string in = "        ";
  out << "      <Grid Name=\"" << name << "\" GridType=\"Uniform\">\n"
      << in << "<Time Value=\"" << time << "\"/>\n"
      << in << "<Topology TopologyType=\"2DSMesh\" Dimensions=\"" << gridDims << "\"/>\n"
      << in << "<Geometry GeometryType=\"XY\">" << hdfItem(h5, xdmfGeometryPath(), gridDims + " 2") << "</Geometry>\n";
}

}  // namespace

std::string xdmfDocument(const ResultLayout& layout, const std::string& hdf5File, const std::vector<StepScalars>& steps) {
  const std::string h5 = escape(hdf5File) + ":";
  const std::string gridDims = dims({layout.ny, layout.nx});
  std::ostringstream out;
  openCollection(out, "PeriStep");
  for (std::size_t k = 0; k < steps.size(); ++k) {
    openGrid(out, "step " + std::to_string(k + 1), exactText(steps[k].time), h5, gridDims);
    for (const ArrayInfo& f : layout.fields)
      if (layout.onGrid(f)) attribute(out, f.name, "Node", hdfItem(h5, xdmfFieldPath(k, f.name), gridDims));
    for (const ArrayInfo& a : layout.constantArrays)
      if (a.name != "x" && a.name != "y") attribute(out, a.name, "Node", hdfItem(h5, "/grid/" + a.name, gridDims));
    if (!layout.inputName.empty()) attribute(out, layout.inputName, "Grid", xmlItem(steps[k].input));
    for (std::size_t i = 0; i < layout.scalars.size(); ++i)
      attribute(out, layout.scalars[i].name, "Grid", xmlItem(steps[k].scalars[i]));
    out << "      </Grid>\n";
  }
  closeCollection(out);
  return out.str();
}

void writeXdmf(const std::filesystem::path& file, const ResultLayout& layout, const std::string& hdf5File,
               const std::vector<StepScalars>& steps) {
  writeFileAtomically(file, xdmfDocument(layout, hdf5File, steps));
}

std::string studyXdmfDocument(const ResultLayout& layout, const std::string& hdf5File,
                              const std::vector<StudyXdmfLevel>& levels) {
  const std::string h5 = escape(hdf5File) + ":";
  const std::string gridDims = dims({layout.ny, layout.nx});
  std::ostringstream out;
  openCollection(out, "PeriStep study");
  for (const StudyXdmfLevel& level : levels) {
    const std::string group = "/level_" + std::to_string(level.level) + "/";
    openGrid(out, "level " + std::to_string(level.level), std::to_string(level.samples), h5, gridDims);
    for (const std::string& statistic : level.statistics)
      for (const ArrayInfo& f : layout.fields)
        if (layout.onGrid(f))
          attribute(out, statistic + "_" + f.name, "Node", hdfItem(h5, group + statistic + "/" + f.name, gridDims));
    for (const auto& [name, value] : level.scalars) attribute(out, name, "Grid", xmlItem(value));
    out << "      </Grid>\n";
  }
  closeCollection(out);
  return out.str();
}

void writeStudyXdmf(const std::filesystem::path& file, const ResultLayout& layout, const std::string& hdf5File,
                    const std::vector<StudyXdmfLevel>& levels) {
  writeFileAtomically(file, studyXdmfDocument(layout, hdf5File, levels));
}

}  // namespace peristep::host
