#include "run_picture.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <variant>

#include "damage_picture.hpp"
#include "gnuplot.hpp"
#include "load_quantity.hpp"
#include "unit_scale.hpp"

namespace peristep::host {

namespace {

std::string hex(const Rgb& c) {
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x", c.r, c.g, c.b);
  return buffer;
}

// The values of a grid array of the step (a field) or of the run (a constant array such as x), or null.
const std::vector<double>* gridValues(const ResultLayout& layout, const StepValues& step, const std::string& name) {
  for (std::size_t i = 0; i < layout.fields.size(); ++i)
    if (layout.fields[i].name == name && layout.onGrid(layout.fields[i])) return &step.fields[i];
  for (std::size_t i = 0; i < layout.constantArrays.size(); ++i)
    if (layout.constantArrays[i].name == name && layout.onGrid(layout.constantArrays[i])) return &layout.constantValues[i];
  return nullptr;
}

std::string unitOf(const ResultLayout& layout, const std::string& name) {
  for (const ArrayInfo& f : layout.fields)
    if (f.name == name) return f.unit.empty() ? "-" : f.unit;
  return "-";
}

std::string textParameter(const ResultLayout& layout, const std::string& name) {
  for (const Attribute& a : layout.parameterAttributes)
    if (a.name == name)
      if (const auto* s = std::get_if<std::string>(&a.value)) return *s;
  return "";
}

// The grid as gnuplot's `binary array` sees it: the lattice of the first row and column (points may
// be jittered by a fraction of h; the picture puts them on the lattice), in the length unit
// unit_scale picks for the coordinates of the domain's edges.
struct Frame {
  double x0 = 0, y0 = 0, dx = 1, dy = 1, scale = 1;
  std::string unit;
  std::string binary(std::uint64_t nx, std::uint64_t ny, const char* format) const {
    std::ostringstream s;
    s.precision(17);
    s << "binary array=(" << nx << ',' << ny << ") dx=" << dx * scale << " dy=" << dy * scale << " origin=(" << x0 * scale
      << ',' << y0 * scale << ") format='" << format << "'";
    return s.str();
  }
};

Frame frame(const ResultLayout& layout, const std::vector<double>& x, const std::vector<double>& y) {
  Frame f;
  const std::size_t nx = layout.nx, ny = layout.ny;
  f.x0 = x[0];
  f.y0 = y[0];
  f.dx = nx > 1 ? (x[nx - 1] - x[0]) / static_cast<double>(nx - 1) : 1.0;
  f.dy = ny > 1 ? (y[(ny - 1) * nx] - y[0]) / static_cast<double>(ny - 1) : f.dx;
  if (nx == 1) f.dx = f.dy;
  const double farthest = std::max({std::abs(f.x0 - 0.5 * f.dx), std::abs(f.x0 + (static_cast<double>(nx) - 0.5) * f.dx),
                                    std::abs(f.y0 - 0.5 * f.dy), std::abs(f.y0 + (static_cast<double>(ny) - 0.5) * f.dy)});
  const ScaledUnit length = scaledUnit("m", farthest);
  f.scale = length.factor;
  f.unit = length.unit;
  return f;
}

std::string header(const std::filesystem::path& png, const ResultLayout& layout, const StepValues& step,
                   const PictureCaption& caption, const Frame& f) {
  const PictureSize size = runPictureSize(layout);
  std::string load;
  if (const LoadQuantity q = loadQuantity(layout, caption.inputUnit); !layout.inputName.empty() && !q.unused) {
    const ScaledUnit unit = scaledUnit(q.unit, std::abs(q.perInput * step.input));
    load = ", " + q.name + " = " + shortNumber(q.perInput * step.input * unit.factor) + (unit.unit.empty() ? "" : " " + unit.unit);
  }
  const ScaledUnit time = scaledUnit("s", std::abs(step.time));
  const double half = 0.5;
  std::ostringstream s;
  s.precision(17);
  s << "set encoding utf8\n"
    << "set terminal pngcairo size " << size.width << ',' << size.height << " font ',11'\n"
    << "set output " << gnuplotQuoted(png.string()) << "\n"
    << "set title " << gnuplotQuoted(caption.scene) << ".\"\\n\"." // a quoted string cannot hold a line break
    << gnuplotQuoted("step " + std::to_string(caption.step) + " of " + std::to_string(caption.steps) + ", t = " +
                     shortNumber(step.time * time.factor) + " " + time.unit + load)
    << " noenhanced\n"
    << "set xlabel 'x [" << f.unit << "]'\nset ylabel 'y [" << f.unit << "]'\n"
    << "set size ratio -1\n"
    << "set xrange [" << (f.x0 - half * f.dx) * f.scale << ':' << (f.x0 + (static_cast<double>(layout.nx) - half) * f.dx) * f.scale
    << "]\nset yrange [" << (f.y0 - half * f.dy) * f.scale << ':'
    << (f.y0 + (static_cast<double>(layout.ny) - half) * f.dy) * f.scale << "]\n"
    << "set tics out\nset key below horizontal noenhanced\nset cblabel noenhanced\n";
  return s.str();
}

// "E = 80 GPa", or the range of a phase whose points differ (a random field): "E = 61.2-98.7 GPa".
std::string modulusText(double lo, double hi) {
  const ScaledUnit pa = scaledUnit("Pa", hi);
  const std::string a = shortNumber(lo * pa.factor), b = shortNumber(hi * pa.factor);
  return "E = " + (a == b ? a : a + "–" + b) + " " + pa.unit;
}

// Phases and cracks: damage_picture's colours as an RGB layer (Void white, as the background: no
// legend entry), the cracks again as a damage layer on the colour bar (same colours), legend entries
// for the phases with their moduli.
std::string damageScript(const ResultLayout& layout, bool cracked, const std::vector<double>* modulus, const Frame& f,
                         const GnuplotData& rgb, const GnuplotData& cracks) {
  std::ostringstream s;
  s << "set cbrange [" << kCrackDamage << ":1]\n"
    << "set palette defined (0 '" << hex(kCrackOnset) << "', 1 '" << hex(kCrackFull) << "')\n"
    << "set cblabel 'damage (broken fraction of bonds) [" << unitOf(layout, "damage") << "]'\n"
    << "plot " << gnuplotQuoted(rgb.path().string()) << ' ' << f.binary(layout.nx, layout.ny, "%uchar%uchar%uchar")
    << " with rgbimage notitle";
  if (cracked)
    s << ", \\\n  " << gnuplotQuoted(cracks.path().string()) << ' ' << f.binary(layout.nx, layout.ny, "%float64")
      << " with image notitle";
  else  // without a layer on the palette there is no colour bar: one point outside the view keeps it
    s << ", \\\n  '-' using 1:2:3 with points lc palette notitle";

  for (const auto& [colour, label] : phaseLegend(layout, modulus ? *modulus : std::vector<double>{}))
    s << ", \\\n  keyentry with boxes fill solid 1.0 fc rgb '" << hex(colour) << "' title " << gnuplotQuoted(label);
  s << ", \\\n  keyentry with boxes fill solid 1.0 fc rgb '" << hex(kCrackFull) << "' title "
    << gnuplotQuoted("crack (damage ≥ " + shortNumber(kCrackDamage) + ")") << "\n";
  if (!cracked) s << "1e30 1e30 1\ne\n";
  return s.str();
}

// 1, 2 or 5 times a power of ten, at most v.
double roundDown125(double v) {
  const double p = std::pow(10.0, std::floor(std::log10(v)));
  for (double m : {5.0, 2.0, 1.0})
    if (m * p <= v) return m * p;
  return p;
}

// |u| as an image and the grid deformed by u (every k-th line, magnified).
std::string displacementScript(const ResultLayout& layout, const std::vector<double>& x, const std::vector<double>& y,
                               const std::vector<double>& ux, const std::vector<double>& uy, const Frame& f,
                               const ScaledUnit& unit, const GnuplotData& magnitude) {
  const std::size_t nx = layout.nx, ny = layout.ny;
  double largest = 0;
  for (std::size_t i = 0; i < ux.size(); ++i) largest = std::max(largest, std::hypot(ux[i], uy[i]));
  const double extent = std::max(f.dx * static_cast<double>(nx), f.dy * static_cast<double>(ny));
  // Largest displacement drawn as 5% of the domain: visible, and the grid does not fold.
  const double magnify = largest > 0 ? roundDown125(0.05 * extent / largest) : 1.0;
  const std::size_t every = std::max<std::size_t>(1, std::max(nx, ny) / 24);

  std::ostringstream s;
  s.precision(9);
  s << "$grid << EOD\n";
  const auto point = [&](std::size_t i) {
    s << (x[i] + magnify * ux[i]) * f.scale << ' ' << (y[i] + magnify * uy[i]) * f.scale << '\n';
  };
  for (std::size_t j = 0; j < ny; j += every) {
    for (std::size_t i = 0; i < nx; ++i) point(j * nx + i);
    s << '\n';
  }
  for (std::size_t i = 0; i < nx; i += every) {
    for (std::size_t j = 0; j < ny; ++j) point(j * nx + i);
    s << '\n';
  }
  s << "EOD\n"
    << "set palette defined (0 '#440154', 0.25 '#3b528b', 0.5 '#21918c', 0.75 '#5ec962', 1 '#fde725')\n"
    << "set cbrange [0:" << (largest > 0 ? largest * unit.factor : 1.0) << "]\n"
    << "set format cb '%.3g'\n"
    << "set cblabel " << gnuplotQuoted("displacement magnitude |u| [" + unit.unit + "]") << "\n"
    << "plot " << gnuplotQuoted(magnitude.path().string()) << ' ' << f.binary(nx, ny, "%float64")
    << " with image notitle, \\\n  $grid with lines lc rgb 'white' lw 0.8 title "
    << gnuplotQuoted(largest > 0 ? "grid deformed by u × " + shortNumber(magnify) : "grid (no displacement)") << "\n";
  return s.str();
}

}  // namespace

std::vector<std::pair<Rgb, std::string>> phaseLegend(const ResultLayout& layout, const std::vector<double>& youngsModulus) {
  const bool glassCeramic =
      textParameter(layout, "scene") == "glassCeramic" || textParameter(layout, "materialField") == "glassCeramic";
  const PhaseModuli phases = phaseModuli(youngsModulus);
  if (phases.two)
    return {{kSoftPhase, (glassCeramic ? "glass, " : "") + modulusText(phases.softLo, phases.softHi)},
            {kStiffPhase, (glassCeramic ? "crystal, " : "") + modulusText(phases.stiffLo, phases.stiffHi)}};
  if (phases.points > 0) return {{kUniformPhase, "material, " + modulusText(phases.softLo, phases.softHi)}};
  if (youngsModulus.empty()) return {{kUniformPhase, "material"}};
  return {};  // Void everywhere: nothing to name
}

PictureSize runPictureSize(const ResultLayout& layout) {
  constexpr double kPlotWidth = 700, kMargins = 190;  // left labels, colour bar; title, x label, legend
  const double aspect = layout.nx > 0 ? static_cast<double>(layout.ny) / static_cast<double>(layout.nx) : 1.0;
  return {1000, static_cast<unsigned>(std::clamp(std::lround(kMargins + kPlotWidth * aspect), 400L, 1300L))};
}

std::string writeRunPicture(const std::filesystem::path& png, const ResultLayout& layout, const StepValues& step,
                            const PictureCaption& caption) {
  const std::vector<double>* x = gridValues(layout, step, "x");
  const std::vector<double>* y = gridValues(layout, step, "y");
  if (!x || !y) return "no point coordinates x, y on the grid";
  const Frame f = frame(layout, *x, *y);
  if (!(f.dx > 0 && f.dy > 0)) return "the grid's points do not span an area";
  const std::string top = header(png, layout, step, caption, f);

  const std::vector<double>* damage = gridValues(layout, step, "damage");
  if (damage && std::any_of(damage->begin(), damage->end(), [](double d) { return d > 0; })) {
    const std::vector<double>* modulus = gridValues(layout, step, "youngsModulus");
    const RgbImage image = damagePicture(layout.ny, layout.nx, *damage, modulus ? *modulus : std::vector<double>{});
    std::vector<double> cracks(damage->size(), std::numeric_limits<double>::quiet_NaN());
    bool cracked = false;
    for (std::size_t i = 0; i < cracks.size(); ++i)
      if ((*damage)[i] >= kCrackDamage && image.pixels[i] != kVoid) cracks[i] = std::min((*damage)[i], 1.0), cracked = true;
    const GnuplotData rgb(image.pixels.data(), image.pixels.size() * sizeof(Rgb));
    const GnuplotData crackData(cracks.data(), cracks.size() * sizeof(double));
    return runGnuplot(top + damageScript(layout, cracked, modulus, f, rgb, crackData), png);
  }
  const std::vector<double>* ux = gridValues(layout, step, "ux");
  const std::vector<double>* uy = gridValues(layout, step, "uy");
  if (!ux || !uy) return "no displacement ux, uy on the grid";
  std::vector<double> magnitude(ux->size());
  double largest = 0;
  for (std::size_t i = 0; i < magnitude.size(); ++i) largest = std::max(largest, magnitude[i] = std::hypot((*ux)[i], (*uy)[i]));
  const std::string unit = unitOf(layout, "ux");
  const ScaledUnit scaled = scaledUnit(unit == "-" ? "" : unit, largest);  // the colour bar's numbers
  for (double& m : magnitude) m *= scaled.factor;
  const GnuplotData data(magnitude.data(), magnitude.size() * sizeof(double));
  return runGnuplot(top + displacementScript(layout, *x, *y, *ux, *uy, f, scaled.unit.empty() ? ScaledUnit{1, "-"} : scaled, data), png);
}

}  // namespace peristep::host
