// Writes api/peristep.h, the C constants of the component for importers, from the variable table and the
// enumeration types (component/fmi/variables.hpp): a value reference per variable, a constant per
// enumeration item. The committed api/peristep.h is a copy that a test keeps identical to this output.
#include <algorithm>
#include <cctype>
#include <fstream>
#include <iostream>
#include <string>

#include "fmi/model_identity.hpp"
#include "fmi/variables.hpp"
#include "scenes/shared_variables.hpp"

namespace {

using namespace peristep::fmi;

// camelCase -> CAMEL_CASE; a digit after a lower-case letter starts a word (material1 -> MATERIAL_1, X0 stays).
std::string capitals(std::string_view name) {
  std::string out;
  for (std::size_t k = 0; k < name.size(); ++k) {
    const char c = name[k], previous = k > 0 ? name[k - 1] : '\0';
    const bool lowerBefore = std::islower(static_cast<unsigned char>(previous)) != 0;
    if (lowerBefore && (std::isupper(static_cast<unsigned char>(c)) || std::isdigit(static_cast<unsigned char>(c))))
      out += '_';
    out += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  }
  return out;
}

std::string dimensions(const Variable& v) {
  std::string out;
  for (fmi3ValueReference d : v.dimensions) {
    out += '[';
    out += findVariable(d)->name;
    out += ']';
  }
  return out;
}

std::string enumName(std::string_view typeName) {  // PeriStep.Grip -> PeriStepGrip
  std::string out(typeName);
  out.erase(std::remove(out.begin(), out.end(), '.'), out.end());
  return out;
}

void writeEnumeration(std::ostream& out, std::string_view typeName, const std::vector<EnumerationItem>& items,
                      std::string_view prefix) {
  out << "enum " << enumName(typeName) << " {\n";
  for (std::size_t k = 0; k < items.size(); ++k) {
    const EnumerationItem& i = items[k];
    out << "  " << (i.cName.empty() ? std::string(prefix) + capitals(i.name) : std::string(i.cName)) << " = " << i.value
        << (k + 1 < items.size() ? "," : "") << " /* " << i.name << " */\n";
  }
  out << "};\n\n";
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: generate_api_header OUT.h\n";
    return 2;
  }
  std::ofstream out(argv[1]);
  out << "/* PeriStep's public constants for importers written in C, C++ or Python (ctypes): the value reference\n"
         "   of every variable of modelDescription.xml and the values of its enumerations, with the model\n"
         "   identifier and instantiation token. Generated from the component's declarations\n"
         "   (modelDescription/generate_api_header.cpp): do not edit. Names and numbers are stable; new\n"
         "   variables get new numbers. Arrays [ny][nx] are images stored row by row (x varies fastest). */\n"
         "#ifndef peristep_h\n#define peristep_h\n\n"
      << "#define PERISTEP_MODEL_IDENTIFIER \"" << kModelIdentifier << "\"\n"
      << "/* Must be passed unchanged to fmi3InstantiateCoSimulation (it is also in modelDescription.xml). */\n"
      << "#define PERISTEP_INSTANTIATION_TOKEN \"" << kInstantiationToken << "\"\n\n"
      << "enum PeriStepValueReference {\n";
  const auto& table = variables();
  for (std::size_t k = 0; k < table.size(); ++k) {
    const Variable& v = table[k];
    out << "  PERISTEP_VR_" << (v.cName.empty() ? capitals(v.name) : std::string(v.cName)) << " = " << v.vr
        << (k + 1 < table.size() ? "," : "") << " /* " << v.name << ": " << typeName(v.type) << dimensions(v)
        << (v.unit.empty() ? "" : ", " + std::string(v.unit)) << ", " << causalityName(v.causality) << " */\n";
  }
  out << "};\n\n";
  for (const EnumerationType& e : enumerationTypes()) writeEnumeration(out, e.name, e.items, e.cPrefix);
  for (const EnumerationType& e : peristep::outputEnumerations()) writeEnumeration(out, e.name, e.items, e.cPrefix);
  out << "#endif\n";
  return out ? 0 : 1;
}
