#include "xdmf_writer.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <system_error>

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

std::string exact(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

// DataItem that reads one step's record out of a [steps][shape...] dataset.
void hyperslab(std::ostream& out, const std::string& indent, const std::string& path, std::size_t step,
               std::size_t steps, const std::vector<std::uint64_t>& itemShape) {
  std::vector<std::uint64_t> full{steps}, count{1};
  full.insert(full.end(), itemShape.begin(), itemShape.end());
  count.insert(count.end(), itemShape.begin(), itemShape.end());
  std::string start = std::to_string(step), stride = "1";
  for (std::size_t i = 0; i < itemShape.size(); ++i) start += " 0", stride += " 1";
  out << indent << "<DataItem ItemType=\"HyperSlab\" Type=\"HyperSlab\" Dimensions=\"" << dims(count) << "\">\n"
      << indent << "  <DataItem Dimensions=\"3 " << full.size() << "\" Format=\"XML\">" << start << "  " << stride
      << "  " << dims(count) << "</DataItem>\n"
      << indent << "  <DataItem Dimensions=\"" << dims(full) << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">"
      << path << "</DataItem>\n"
      << indent << "</DataItem>\n";
}

}  // namespace

std::string xdmfDocument(const ResultLayout& layout, const std::string& hdf5File, const std::vector<double>& times) {
  const std::string h5 = escape(hdf5File);
  const std::string gridDims = dims({layout.ny, layout.nx});
  std::ostringstream out;
  out << "<?xml version=\"1.0\" ?>\n"
      << "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
      << "<Xdmf Version=\"3.0\">\n"
      << "  <Domain>\n"
      << "    <Grid Name=\"PeriStep\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (std::size_t k = 0; k < times.size(); ++k) {
    const std::string in = "        ";
    out << "      <Grid Name=\"step " << k + 1 << "\" GridType=\"Uniform\">\n"
        << in << "<Time Value=\"" << exact(times[k]) << "\"/>\n"
        << in << "<Topology TopologyType=\"2DSMesh\" Dimensions=\"" << gridDims << "\"/>\n"
        << in << "<Geometry GeometryType=\"X_Y\">\n";
    for (const char* axis : {"x", "y"})
      out << in << "  <DataItem Dimensions=\"" << gridDims << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">"
          << h5 << ":/grid/" << axis << "</DataItem>\n";
    out << in << "</Geometry>\n";
    for (const ArrayInfo& f : layout.fields) {
      if (!layout.onGrid(f)) continue;  // only fields on the points can be drawn on the grid
      out << in << "<Attribute Name=\"" << escape(f.name) << "\" AttributeType=\"Scalar\" Center=\"Node\">\n";
      hyperslab(out, in + "  ", h5 + ":/fields/" + escape(f.name), k, times.size(), f.shape);
      out << in << "</Attribute>\n";
    }
    for (std::size_t i = 0; i < layout.constantArrays.size(); ++i) {
      const ArrayInfo& a = layout.constantArrays[i];
      if (a.name == "x" || a.name == "y") continue;  // already the geometry
      out << in << "<Attribute Name=\"" << escape(a.name) << "\" AttributeType=\"Scalar\" Center=\"Node\">\n"
          << in << "  <DataItem Dimensions=\"" << gridDims << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">"
          << h5 << ":/grid/" << escape(a.name) << "</DataItem>\n"
          << in << "</Attribute>\n";
    }
    for (const ArrayInfo& s : layout.scalars) {
      out << in << "<Attribute Name=\"" << escape(s.name) << "\" AttributeType=\"Scalar\" Center=\"Grid\">\n";
      hyperslab(out, in + "  ", h5 + ":/scalars/" + escape(s.name), k, times.size(), {});
      out << in << "</Attribute>\n";
    }
    out << "      </Grid>\n";
  }
  out << "    </Grid>\n"
      << "  </Domain>\n"
      << "</Xdmf>\n";
  return out.str();
}

void writeXdmf(const std::filesystem::path& file, const ResultLayout& layout, const std::string& hdf5File,
               const std::vector<double>& times) {
  std::filesystem::path temporary = file;
  temporary += ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out << xdmfDocument(layout, hdf5File, times);
    if (!out) throw RunError(temporary.string() + ": cannot write the XDMF file");
  }
  std::error_code ec;
  std::filesystem::rename(temporary, file, ec);
  if (ec) throw RunError(file.string() + ": cannot write the XDMF file: " + ec.message());
}

}  // namespace peristep::host
