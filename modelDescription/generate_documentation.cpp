// Writes the FMU's documentation/index.html from the component's variable table, its enumerations,
// units and log categories: the same sources as modelDescription.xml, so the page cannot drift from it.
// Everything an importer needs is on the page itself (value references, enumeration values), because the
// FMU archive holds no header.
//
//   generate_documentation <index.html>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>

#include "fmi/log_categories.hpp"
#include "fmi/variables.hpp"
#include "model_summary.hpp"
#include "fmi/model_identity.hpp"

using namespace peristep::fmi;

namespace {

std::string escaped(std::string_view text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '&': out += "&amp;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string code(std::string_view text) { return "<code>" + escaped(text) + "</code>"; }

std::string cell(const std::string& html) { return "<td>" + html + "</td>"; }

// "[1, 20]", "(0, inf)": the admissible interval, open ends in round brackets.
std::string range(const Variable& v) {
  if (!v.min && !v.max) return "";
  std::string r;
  if (v.min) r.append(v.min->open ? "(" : "[").append(number(v.min->value));
  else r.append("(-inf");
  r.append(", ");
  if (v.max) r.append(number(v.max->value)).append(v.max->open ? ")" : "]");
  else r.append("inf)");
  return r;
}

std::string dimensions(const Variable& v) {
  std::string d;
  for (fmi3ValueReference s : v.dimensions) d.append("[").append(findVariable(s)->name).append("]");
  return d;
}

// Outputs: the inputs the output depends on (as in <Output dependencies>); "every known" where unset.
std::string dependsOn(const Variable& v) {
  if (v.causality != Causality::Output) return "";
  if (!v.dependencies) return "every known";
  if (v.dependencies->empty()) return "no input";
  std::string d;
  for (fmi3ValueReference r : *v.dependencies) d.append(d.empty() ? "" : ", ").append(code(findVariable(r)->name));
  return d;
}

std::string unit(const UnitDefinition& u) {
  if (!u.integerPowers) return "no SI base-unit form with integer powers";
  std::string s;
  const auto power = [&s](const char* base, int p) {
    if (!p) return;
    if (!s.empty()) s += ' ';
    s += base;
    if (p != 1) s += '^' + std::to_string(p);
  };
  power("kg", u.kg);
  power("m", u.m);
  power("s", u.s);
  return s;
}

void writeVariables(std::ostream& out) {
  out << "<h2 id=\"variables\">Variables</h2>\n"
         "<p>Arrays are <code>[ny][nx]</code> images with x varying fastest, or vectors of length "
         "<code>nModes</code>; an array's start value holds for every element. Enumerations are read and "
         "written with <code>fmi3GetInt64</code>/<code>fmi3SetInt64</code>.</p>\n"
         "<table>\n<tr><th>Name</th><th>Value reference</th><th>Type</th><th>Causality</th><th>Variability</th>"
         "<th>Unit</th><th>Dimensions</th><th>Start</th><th>Range</th><th>Output depends on</th><th>Description</th>"
         "</tr>\n";
  for (const Variable& v : variables()) {
    const std::string type = v.declaredType.empty() ? std::string(typeName(v.type))
                                                    : std::string(typeName(v.type)) + " " + code(v.declaredType);
    out << "<tr id=\"var-" << escaped(v.name) << "\">" << cell(code(v.name)) << cell(std::to_string(v.vr))
        << cell(type) << cell(std::string(causalityName(v.causality)))
        << cell(std::string(variabilityName(v.variability))) << cell(escaped(v.unit)) << cell(escaped(dimensions(v)))
        << cell(escaped(v.start)) << cell(range(v)) << cell(dependsOn(v)) << cell(escaped(v.description)) << "</tr>\n";
  }
  out << "</table>\n";
}

void writeEnumerations(std::ostream& out) {
  out << "<h2 id=\"enumerations\">Enumerations</h2>\n";
  for (const EnumerationType& e : enumerationTypes()) {
    out << "<h3>" << code(e.name) << "</h3>\n<p>" << escaped(e.description)
        << "</p>\n<table>\n<tr><th>Item</th><th>Value</th><th>Description</th></tr>\n";
    for (const EnumerationItem& item : e.items)
      out << "<tr>" << cell(code(item.name)) << cell(std::to_string(item.value)) << cell(escaped(item.description))
          << "</tr>\n";
    out << "</table>\n";
  }
}

// How the load reaches a quasi-static scene in the common importers, and what to know about the dynamic
// scenes' microsecond steps. input_loadFactor.csv ships beside this page.
void writeImporters(std::ostream& out) {
  out << "<h2 id=\"importers\">Loading a scene from fmusim or FMPy</h2>\n"
         "<p>A quasi-static scene does nothing by itself: each <code>fmi3DoStep</code> solves at the value its "
         "load input holds during the step (<code>loadFactor</code>, or <code>loadDisplacement</code> for "
         "<code>glassCeramic</code>), and the start values are 0. Give the load as an input signal. "
         "<code>input_loadFactor.csv</code> beside this page ramps <code>loadFactor</code> from 0 to 1 over "
         "the default experiment; with the start values (Test 1 of 000 on 33 x 33 points):</p>\n"
         "<pre>fmusim --input-file input_loadFactor.csv --output-interval 0.25 PeriStep.fmu</pre>\n"
         "<p>In FMPy, pass the same signal as a structured array with fields <code>time</code> and "
         "<code>loadFactor</code> to <code>simulate_fmu(..., input=signal, output_interval=0.25)</code>. "
         "An importer applies the input at the start of each step, so step k solves at the load of time "
         "t<sub>k</sub>. For <code>glassCeramic</code> set <code>scene</code>, <code>nx</code>, "
         "<code>ny</code>, <code>Lx</code> and <code>Ly</code> as start values and ramp "
         "<code>loadDisplacement</code> (0 to 3e-7 m reaches the crack's run on the coarse grids). FMPy "
         "before 0.3.24 cannot read the <code>description</code> attribute of <code>&lt;EnumerationType&gt;</code>, "
         "which FMI 3.0 allows; FMPy does not set structural parameters (<code>nx</code>, <code>ny</code>, "
         "<code>nModes</code>, ...), so it runs the start values' grid.</p>\n"
         "<p>The dynamic scenes step in microseconds (<code>learnedFracture</code> in 5e-14 s frames). fmusim "
         "releases that compare communication times to a tolerance of about 1e-5 s end such a run early, "
         "with status 0 and no message, after the first steps; run these scenes with the host "
         "(<code>peristep run scenes/plexiglass_crack.toml</code>), with FMPy, or with an importer that steps "
         "to the given stop time exactly, and check that the last output time is the stop time.</p>\n";
}

void writePage(const char* path) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error(std::string("cannot open ") + path);
  out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>PeriStep FMU</title>\n"
         "<style>table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:2px 6px;"
         "vertical-align:top}</style>\n</head>\n<body>\n<h1>PeriStep "
      << PERISTEP_VERSION << "</h1>\n<p>" << escaped(kModelSummary)
      << ".</p>\n<p>An FMI 3.0 Co-Simulation FMU for x86_64 Linux (model identifier <code>"
      << kModelIdentifier << "</code>, instantiation token <code>" << kInstantiationToken
      << "</code>). This page is generated from the variable table that modelDescription.xml is generated from."
         " References such as 000:(5.2) name an equation of Fan et al., A meshfree peridynamic model for brittle "
         "fracture in randomly heterogeneous materials, CMAME 399 (2022) 115340; 001 is Jha and Lipton, Numerical "
         "convergence of finite difference approximations for state based peridynamic fracture models, CMAME 351 "
         "(2019) 184-225.</p>\n\n"
         "<h2>How to run it</h2>\n<ol>\n"
         "<li>Optionally enter Configuration Mode and set the structural parameters <code>nx</code>, "
         "<code>ny</code> (points per side) and <code>nModes</code> (length of <code>xi</code>).</li>\n"
         "<li>Set the parameters (<code>scene</code>, <code>Lx</code>, <code>Ly</code>, <code>deltaOverH</code>, "
         "<code>poissonRatio</code>, <code>xi</code>, ...) in Instantiated or Initialization Mode. The spacing "
         "must be uniform: <code>h = Lx/(nx-1) = Ly/(ny-1)</code>, the same point grid in every scene.</li>\n"
         "<li><code>fmi3ExitInitializationMode</code> builds the scene and computes the outputs at the current "
         "inputs.</li>\n"
         "<li>Each <code>fmi3DoStep</code> of a quasi-static scene is one load increment: it solves at the current "
         "<code>loadFactor</code> (or, for <code>glassCeramic</code>, <code>loadDisplacement</code>) whatever the "
         "step size. Each <code>fmi3DoStep</code> of a dynamic scene integrates the equation of motion over the "
         "communication step, in internal steps of <code>internalTimeStep</code>.</li>\n</ol>\n\n"
         "<h2 id=\"experiments\">Step size and stop time of each scene</h2>\n"
         "<p>The default experiment (start "
      << number(kDefaultExperiment.startTime) << " s, stop " << number(kDefaultExperiment.stopTime)
      << " s, step " << number(kDefaultExperiment.stepSize)
      << " s) fits the quasi-static scenes. The dynamic scenes need communication steps of microseconds: with "
         "the default step an <code>fmi3DoStep</code> of <code>plexiglassCrack</code> would take "
      << std::llround(kDefaultExperiment.stepSize / 4e-9)  // the Plexiglass step of 001
      << " internal steps. Each scene's recommended step and stop time:</p>\n<table>\n"
         "<tr><th>scene</th><th>Value</th><th>Description, step size and stop time</th></tr>\n";
  for (const EnumerationItem& s : findEnumeration("PeriStep.Scene")->items)
    out << "<tr>" << cell(code(s.name)) << cell(std::to_string(s.value)) << cell(escaped(s.description)) << "</tr>\n";
  out << "</table>\n\n";
  writeImporters(out);
  writeVariables(out);
  writeEnumerations(out);
  out << "<h2>Units</h2>\n<table>\n<tr><th>Unit</th><th>SI base units</th></tr>\n";
  for (const UnitDefinition& u : unitDefinitions()) out << "<tr>" << cell(code(u.name)) << cell(unit(u)) << "</tr>\n";
  out << "</table>\n<h2>Log categories</h2>\n<table>\n<tr><th>Category</th><th>Description</th></tr>\n";
  for (const LogCategoryInfo& c : kLogCategories)
    out << "<tr>" << cell(code(c.name)) << cell(escaped(c.description)) << "</tr>\n";
  out << "</table>\n\n"
         "<h2>Behaviour worth knowing</h2>\n<ul>\n"
         "<li>Any call that returns <code>fmi3Error</code> logs one message in category <code>logStatusError</code>, "
         "whatever <code>loggingOn</code> says, and leaves the instance in Terminated, as FMI 3.0 requires: "
         "restore an FMU state or call <code>fmi3Reset</code> to continue.</li>\n"
         "<li>No step returns <code>fmi3OK</code> with an output that is not finite: a load, velocity or restored "
         "state that drives the solution out of double precision is refused with the quantity named.</li>\n"
         "<li>A run gives the same bits on any number of OpenMP threads when OpenBLAS runs on one thread "
         "(<code>OPENBLAS_NUM_THREADS=1</code>, as <code>peristep</code> sets it): OpenBLAS' own results change "
         "in the last bits with its thread count.</li>\n"
         "<li>In Step Mode, values may not be read after a value was set until the next "
         "<code>fmi3DoStep</code>.</li>\n"
         "<li>FMU states can be saved, restored and serialized.</li>\n"
         "<li>Each output's description names the scenes that compute it and what it reads in the "
         "others.</li>\n</ul>\n</body>\n</html>\n";
  if (!out) throw std::runtime_error(std::string("cannot write ") + path);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s <index.html>\n", argv[0]);
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
