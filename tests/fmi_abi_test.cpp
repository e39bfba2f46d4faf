// PeriStep.so seen only through dlopen() and the exported FMI 3.0 functions: what is exported, a
// full co-simulation run with the start values and the DefaultExperiment, and independent
// instances stepping on two threads.
#include <algorithm>
#include <elf.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <thread>

#include "fmi_abi_support.hpp"

namespace {

// Names of the symbols PeriStep.so defines and exports (read from its .dynsym section).
std::vector<std::string> exportedSymbols(const char* path) {
  std::ifstream in(path, std::ios::binary);
  const std::vector<char> file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  REQUIRE(file.size() > sizeof(Elf64_Ehdr));
  Elf64_Ehdr header;
  std::memcpy(&header, file.data(), sizeof header);
  REQUIRE(std::memcmp(header.e_ident, ELFMAG, SELFMAG) == 0);
  REQUIRE(header.e_ident[EI_CLASS] == ELFCLASS64);
  std::vector<Elf64_Shdr> sections(header.e_shnum);
  REQUIRE(header.e_shoff + sections.size() * sizeof(Elf64_Shdr) <= file.size());
  std::memcpy(sections.data(), file.data() + header.e_shoff, sections.size() * sizeof(Elf64_Shdr));
  std::vector<std::string> names;
  for (const Elf64_Shdr& s : sections) {
    if (s.sh_type != SHT_DYNSYM) continue;
    const Elf64_Shdr& strings = sections.at(s.sh_link);
    for (std::size_t k = 1; k < s.sh_size / sizeof(Elf64_Sym); ++k) {
      Elf64_Sym sym;
      std::memcpy(&sym, file.data() + s.sh_offset + k * sizeof(Elf64_Sym), sizeof sym);
      const int binding = ELF64_ST_BIND(sym.st_info);
      if (sym.st_shndx == SHN_UNDEF || (binding != STB_GLOBAL && binding != STB_WEAK && binding != STB_GNU_UNIQUE))
        continue;
      names.emplace_back(file.data() + strings.sh_offset + sym.st_name);
    }
  }
  return names;
}

struct Outputs {
  std::vector<double> ux, uy, damage, scalars;
  bool operator==(const Outputs&) const = default;
};

constexpr fmi3ValueReference kScalarOutputs[] = {
    PERISTEP_VR_REACTION_FORCE, PERISTEP_VR_CRACK_LENGTH, PERISTEP_VR_BROKEN_BONDS, PERISTEP_VR_STRAIN_ENERGY,
    PERISTEP_VR_FRACTURE_ENERGY, PERISTEP_VR_TOUGHNESS_KIC, PERISTEP_VR_ERROR_L2};

// Reads every output; false when a call fails. No Catch assertions here: threads call it too.
bool readOutputs(Session& s, std::size_t points, Outputs& o) {
  o = {s.getFloat64(PERISTEP_VR_UX, points), s.getFloat64(PERISTEP_VR_UY, points),
       s.getFloat64(PERISTEP_VR_DAMAGE, points), std::vector<double>(std::size(kScalarOutputs))};
  return !o.ux.empty() && !o.uy.empty() && !o.damage.empty() &&
         s.fmu.fmi3GetFloat64(s.instance, kScalarOutputs, std::size(kScalarOutputs), o.scalars.data(),
                              o.scalars.size()) == fmi3OK;
}

// A scene on an n x n grid, initialized and stepped through loads 0.25, 0.5, 0.75, 1: the outputs
// of every step, or false when any call fails or logs an error.
bool scenario(std::int64_t scene, std::uint64_t n, double poissonRatio, std::vector<Outputs>& steps,
              std::int64_t solver = PERISTEP_LINEAR_SOLVER_UMFPACK) {
  Session s;
  const std::uint64_t modes = scene == PERISTEP_SCENE_COMPOSITE ? 2 : 1;
  bool ok = s.configure(n, n, modes) == fmi3OK && s.setInt64(PERISTEP_VR_SCENE, scene) == fmi3OK &&
            s.setInt64(PERISTEP_VR_LINEAR_SOLVER, solver) == fmi3OK &&
            s.setFloat64(PERISTEP_VR_POISSON_RATIO, {poissonRatio}) == fmi3OK &&
            s.setFloat64(PERISTEP_VR_XI, std::vector<double>(modes, 0.5)) == fmi3OK && s.initialize() == fmi3OK;
  for (int k = 0; ok && k < 4; ++k) {
    ok = s.setFloat64(PERISTEP_VR_LOAD_FACTOR, {0.25 * (k + 1)}) == fmi3OK && s.step(0.25 * k, 0.25) == fmi3OK &&
         readOutputs(s, n * n, steps.emplace_back());
  }
  return ok && s.log.errors() == 0;
}

// Runs scene A (smooth) and scene B (composite) on 17 x 17 grids one at a time, then both at once
// on two threads; the outputs of every step of the concurrent runs are returned beside the others.
struct ConcurrentRuns {
  std::vector<Outputs> aloneA, aloneB, a, b;
};
ConcurrentRuns runConcurrently(std::int64_t solver) {
  ConcurrentRuns r;
  REQUIRE(scenario(PERISTEP_SCENE_SMOOTH, 17, 0.3, r.aloneA, solver));
  REQUIRE(scenario(PERISTEP_SCENE_COMPOSITE, 17, 0.25, r.aloneB, solver));
  REQUIRE(r.aloneA.back().ux != r.aloneB.back().ux);
  // An exception escaping a thread would end the process: the threads report through okA/okB.
  const auto guarded = [solver](std::int64_t scene, double nu, std::vector<Outputs>& out) {
    try {
      return scenario(scene, 17, nu, out, solver);
    } catch (...) {
      return false;
    }
  };
  bool okA = false, okB = false;
  std::thread ta([&] { okA = guarded(PERISTEP_SCENE_SMOOTH, 0.3, r.a); });
  std::thread tb([&] { okB = guarded(PERISTEP_SCENE_COMPOSITE, 0.25, r.b); });
  ta.join();
  tb.join();
  REQUIRE(okA);
  REQUIRE(okB);
  return r;
}

}  // namespace

TEST_CASE("PeriStep.so exports every FMI 3.0 function and nothing else", "[abi]") {
  const Fmu& fmu = Fmu::get();  // throws naming the first missing function
  CHECK(std::string(fmu.fmi3GetVersion()) == "3.0");
  const auto names = exportedSymbols(PERISTEP_SO_PATH);
  std::size_t fmi3 = 0;
  for (const auto& name : names) {
    INFO("exported symbol " << name);
    CHECK(name.rfind("fmi3", 0) == 0);
    fmi3 += name.rfind("fmi3", 0) == 0;
  }
  CHECK(fmi3 == 75);  // the standard's functions, each once
}

TEST_CASE("a run with the start values and the DefaultExperiment succeeds", "[abi]") {
  Session s;
  // DefaultExperiment: startTime 0, stopTime 1, stepSize 0.25.
  REQUIRE(s.fmu.fmi3EnterInitializationMode(s.instance, fmi3False, 0, 0.0, fmi3True, 1.0) == fmi3OK);
  REQUIRE(s.fmu.fmi3ExitInitializationMode(s.instance) == fmi3OK);
  const std::size_t points = 33 * 33;  // nx = ny = 33
  Outputs initial;
  REQUIRE(readOutputs(s, points, initial));
  double t = 0;
  for (int k = 0; k < 4; ++k) {
    double last = -1;
    REQUIRE(s.step(t, 0.25, &last) == fmi3OK);
    t += 0.25;
    CHECK(last == Approx(t));
    Outputs o;
    REQUIRE(readOutputs(s, points, o));
    REQUIRE(o.ux.size() == points);
    CHECK(o == initial);  // loadFactor stays at its start value 1: the same quasi-static solution
  }
  CHECK(s.getFloat64(PERISTEP_VR_TIME) == std::vector<double>{1.0});
  const double errorL2 = initial.scalars.back();
  INFO("errorL2 = " << errorL2);
  CHECK(std::isfinite(errorL2));
  CHECK(errorL2 > 0);
  CHECK(errorL2 < 1e-3);  // 000 Sec. 4.1: O(delta^2) with delta = 3h, h = 1/32
  double maxU = 0;
  for (double u : initial.ux) maxU = std::max(maxU, std::abs(u));
  CHECK(maxU > 0);
  for (double d : initial.damage) CHECK(d == 0);           // Test 1 cannot break
  for (std::size_t k = 0; k + 1 < std::size(kScalarOutputs); ++k) CHECK(initial.scalars[k] == 0);
  REQUIRE(s.fmu.fmi3Terminate(s.instance) == fmi3OK);
  CHECK(s.getFloat64(PERISTEP_VR_ERROR_L2) == std::vector<double>{errorL2});
  CHECK(s.log.records.empty());  // logging on, nothing to report
}

TEST_CASE("the load factor input scales the quasi-static solution", "[abi]") {
  std::vector<Outputs> steps;
  REQUIRE(scenario(PERISTEP_SCENE_SMOOTH, 9, 0.3, steps));
  for (std::size_t k = 0; k < steps.size(); ++k)
    for (std::size_t p = 0; p < steps[k].ux.size(); ++p) {
      // the problem is linear: u(load) = load * u(1)
      CHECK(steps[k].ux[p] == Approx(0.25 * (k + 1) * steps[3].ux[p]).margin(1e-14));
      CHECK(steps[k].uy[p] == Approx(0.25 * (k + 1) * steps[3].uy[p]).margin(1e-14));
    }
  CHECK(steps[0].ux != steps[3].ux);
}

TEST_CASE("two instances stepping on two threads give the results of one at a time", "[abi][threads]") {
  // The solver library serializes the one process-wide state (METIS's random numbers), so both the
  // default solver and the AMD ordering repeat bit for bit.
  const auto solver = GENERATE(PERISTEP_LINEAR_SOLVER_UMFPACK, PERISTEP_LINEAR_SOLVER_UMFPACK_AMD);
  const ConcurrentRuns r = runConcurrently(solver);
  CHECK(r.a == r.aloneA);
  CHECK(r.b == r.aloneB);
}

TEST_CASE("the glass-ceramic scene reports its fracture outputs through the ABI", "[abi][fracture]") {
  Session s;
  REQUIRE(s.configure(51, 26) == fmi3OK);  // h = 16 um
  REQUIRE(s.setInt64(PERISTEP_VR_SCENE, PERISTEP_SCENE_GLASS_CERAMIC) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_LX, {800e-6}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_LY, {400e-6}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_POISSON_RATIO, {0.25}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_CRYSTAL_FRACTION, {0.0}) == fmi3OK);
  REQUIRE(s.initialize() == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_LOAD_DISPLACEMENT, {0.05e-6}) == fmi3OK);  // below the first break
  REQUIRE(s.step(0.0, 0.25) == fmi3OK);
  const std::size_t n = 51 * 26;
  const auto E = s.getFloat64(PERISTEP_VR_YOUNGS_MODULUS, n);
  for (double e : E) CHECK(e == 80e9);  // f = 0: all glass (000 Table 1)
  const auto damage = s.getFloat64(PERISTEP_VR_DAMAGE, n);
  CHECK(*std::max_element(damage.begin(), damage.end()) > 0.0);  // the pre-crack
  for (double d : damage) CHECK((d >= 0.0 && d <= 1.0));
  CHECK(s.getFloat64(PERISTEP_VR_BROKEN_BONDS)[0] > 0.0);
  CHECK(s.getFloat64(PERISTEP_VR_REACTION_FORCE)[0] > 0.0);  // the top collar pulls up
  CHECK(s.getFloat64(PERISTEP_VR_CRACK_LENGTH)[0] == 0.0);    // nothing grown yet
  CHECK(s.log.records.empty());
}
