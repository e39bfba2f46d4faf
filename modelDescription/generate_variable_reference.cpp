// Writes docs/variables.md, the variable reference for readers of the source tree, from the component's
// variable table: the table modelDescription.xml and the FMU's documentation/index.html come from, so the
// three cannot drift apart (a test compares the committed page with a fresh one).
//
//   generate_variable_reference <variables.md>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>

#include "fmi/variables.hpp"
#include "model_summary.hpp"

using namespace peristep::fmi;

namespace {

// Markdown table cells hold no '|' or line break.
std::string cell(std::string_view text) {
  std::string out;
  for (char c : text) out += c == '|' ? std::string("\\|") : c == '\n' ? std::string(" ") : std::string(1, c);
  return out;
}

std::string code(std::string_view text) { return text.empty() ? "" : "`" + std::string(text) + "`"; }

std::string range(const Variable& v) {
  if (!v.min && !v.max) return "";
  std::string r = v.min ? (v.min->open ? "(" : "[") + number(v.min->value) : "(-inf";
  r += ", ";
  r += v.max ? number(v.max->value) + (v.max->open ? ")" : "]") : "inf)";
  return r;
}

std::string shape(const Variable& v) {
  std::string d;
  for (fmi3ValueReference s : v.dimensions) d += "[" + std::string(findVariable(s)->name) + "]";
  return d;
}

void writePage(const char* path) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error(std::string("cannot open ") + path);
  out << "# Variable reference\n\n"
         "Every variable of `PeriStep.fmu`, generated from the component's variable table by "
         "`modelDescription/generate_variable_reference.cpp` (do not edit by hand: the build writes "
         "`build/variables.md` and a test compares it with this file). Scene files, `--set` and importers name "
         "variables as listed here. Arrays are `[ny][nx]` images (x varying fastest, row 0 at y = -Ly/2) or "
         "vectors; an array's start value holds for every element. `peristep info NAME` prints one in full.\n";
  for (Causality causality : {Causality::StructuralParameter, Causality::Parameter, Causality::CalculatedParameter,
                              Causality::Input, Causality::Output, Causality::Independent}) {
    bool header = false;
    for (const Variable& v : variables()) {
      if (v.causality != causality) continue;
      if (!header) {
        out << "\n## " << causalityName(causality) << "\n\n"
            << "| name | vr | type | unit | shape | start | range | description |\n"
            << "|---|---|---|---|---|---|---|---|\n";
        header = true;
      }
      const std::string type = std::string(typeName(v.type)) + (v.declaredType.empty() ? "" : " " + code(v.declaredType));
      out << "| " << code(v.name) << " | " << v.vr << " | " << cell(type) << " | " << cell(v.unit) << " | "
          << cell(shape(v)) << " | " << cell(v.start) << " | " << cell(range(v)) << " | " << cell(v.description)
          << " |\n";
    }
  }
  out << "\n## Enumerations\n";
  for (const EnumerationType& e : enumerationTypes()) {
    out << "\n### " << code(e.name) << "\n\n" << cell(e.description) << "\n\n| item | value | description |\n|---|---|---|\n";
    for (const EnumerationItem& item : e.items)
      out << "| " << code(item.name) << " | " << item.value << " | " << cell(item.description) << " |\n";
  }
  if (!out) throw std::runtime_error(std::string("cannot write ") + path);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s <variables.md>\n", argv[0]);
    return 2;
  }
  try {
    writePage(argv[1]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", argv[0], e.what());
    return 1;
  }
  return 0;
}
