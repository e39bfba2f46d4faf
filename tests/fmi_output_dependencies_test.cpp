// The <Output dependencies> of modelDescription.xml are true to the code: in every scene, an output that
// changes when one input changes lists that input (FMI 3.0.2 Sec. 2.4.8: an unknown depends on exactly
// the knowns it lists; no attribute means all). Each scene runs on a coarse grid through the C ABI: one
// step at the base inputs, an FMU state saved, then the next step once at the base inputs and once with
// one input changed; the outputs of the two are compared.
#include <catch2/catch.hpp>
#include <functional>
#include <map>
#include <optional>
#include <sstream>

#include "fmi_abi_support.hpp"
#include "model_description_xml.hpp"

namespace {

struct Output {
  std::string name, type;
  fmi3ValueReference vr;
  std::vector<fmi3ValueReference> dimensions;
  std::optional<std::vector<fmi3ValueReference>> dependencies;  // unset: every known
};

std::vector<fmi3ValueReference> references(const std::string& list) {
  std::istringstream in(list);
  std::vector<fmi3ValueReference> out;
  for (fmi3ValueReference r; in >> r;) out.push_back(r);
  return out;
}

// The outputs of the generated modelDescription.xml with their <Output dependencies>.
std::vector<Output> outputs() {
  const XmlDocument doc(PERISTEP_GENERATED_MODEL_DESCRIPTION);
  std::map<fmi3ValueReference, Output> byReference;
  for (xmlNodePtr v : children(firstChild(doc.root(), "ModelVariables"))) {
    if (attribute(v, "causality") != "output") continue;
    Output o{attribute(v, "name"),
             elementName(v),
             static_cast<fmi3ValueReference>(std::stoul(attribute(v, "valueReference"))),
             {},
             {}};
    for (xmlNodePtr d : children(v, "Dimension")) o.dimensions.push_back(std::stoul(attribute(d, "valueReference")));
    byReference.emplace(o.vr, o);
  }
  for (xmlNodePtr e : children(firstChild(doc.root(), "ModelStructure"), "Output"))
    if (const auto deps = optionalAttribute(e, "dependencies"))
      byReference.at(std::stoul(attribute(e, "valueReference"))).dependencies = references(*deps);
  std::vector<Output> out;
  for (auto& [vr, o] : byReference) out.push_back(o);
  return out;
}

// Every element of an output, as doubles.
std::vector<double> read(Session& s, const Output& o) {
  std::size_t n = 1;
  for (fmi3ValueReference d : o.dimensions) {
    fmi3UInt64 size = 0;
    REQUIRE(s.fmu.fmi3GetUInt64(s.instance, &d, 1, &size, 1) == fmi3OK);
    n *= size;
  }
  if (o.type == "Float64") {
    std::vector<double> v = s.getFloat64(o.vr, n);
    REQUIRE(v.size() == n);
    return v;
  }
  REQUIRE(o.type == "Int32");  // a new output type needs its reader here
  std::vector<fmi3Int32> v(n);
  REQUIRE(s.fmu.fmi3GetInt32(s.instance, &o.vr, 1, v.data(), n) == fmi3OK);
  return {v.begin(), v.end()};
}

struct Scene {
  const char* name;
  std::function<void(Session&)> setUp;  // Configuration and parameters
  double step;                          // communication step [s]
  fmi3ValueReference drivenBy;          // the input that must change some output
};

const fmi3ValueReference kInputs[] = {PERISTEP_VR_LOAD_FACTOR, PERISTEP_VR_LOAD_DISPLACEMENT};
constexpr double kBase[] = {1.0, 0.05e-6}, kChanged[] = {0.5, 0.25e-6};  // loadFactor, loadDisplacement [m]

void setInputs(Session& s, const double (&values)[2]) {
  REQUIRE(s.fmu.fmi3SetFloat64(s.instance, kInputs, 2, values, 2) == fmi3OK);
}

// The outputs after two steps, the first at the base inputs, the second at `second`. Fresh instances
// rather than one restored FMU state: forceEvaluations counts work across fmi3SetFMUState.
std::vector<std::vector<double>> run(const Scene& scene, const double (&second)[2], const std::vector<Output>& all) {
  Session s;
  scene.setUp(s);
  REQUIRE(s.initialize(0, 1) == fmi3OK);
  setInputs(s, kBase);
  REQUIRE(s.step(0, scene.step) == fmi3OK);
  setInputs(s, second);
  REQUIRE(s.step(scene.step, scene.step) == fmi3OK);
  std::vector<std::vector<double>> values;
  for (const Output& o : all) values.push_back(read(s, o));
  CHECK(s.log.errors() == 0);
  return values;
}

void grid(Session& s, std::int64_t scene, std::uint64_t nx, std::uint64_t ny, std::uint64_t modes = 1) {
  REQUIRE(s.configure(nx, ny, modes) == fmi3OK);
  REQUIRE(s.setInt64(PERISTEP_VR_SCENE, scene) == fmi3OK);
}

void dynamic(Session& s, std::int64_t scene, std::uint64_t nx, std::uint64_t ny, double Lx, double Ly,
             double deltaOverH, double internalStep) {
  grid(s, scene, nx, ny);
  REQUIRE(s.setFloat64(PERISTEP_VR_LX, {Lx}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_LY, {Ly}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_DELTA_OVER_H, {deltaOverH}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_POISSON_RATIO, {0.25}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_INTERNAL_TIME_STEP, {internalStep}) == fmi3OK);
}

}  // namespace

TEST_CASE("every output lists the inputs it depends on in every scene", "[modelDescription][dependencies]") {
  const std::vector<Output> all = outputs();
  REQUIRE(all.size() > 10);
  const std::vector<Scene> scenes{
      {"smooth", [](Session& s) { grid(s, PERISTEP_SCENE_SMOOTH, 9, 9); }, 0.25, PERISTEP_VR_LOAD_FACTOR},
      {"composite", [](Session& s) { grid(s, PERISTEP_SCENE_COMPOSITE, 9, 9, 2); }, 0.25, PERISTEP_VR_LOAD_FACTOR},
      {"interfaceCrack", [](Session& s) { grid(s, PERISTEP_SCENE_INTERFACE_CRACK, 9, 9, 2); }, 0.25,
       PERISTEP_VR_LOAD_FACTOR},
      {"klPlate", [](Session& s) { grid(s, PERISTEP_SCENE_KL_PLATE, 9, 9, 2); }, 0.25, PERISTEP_VR_LOAD_FACTOR},
      {"glassCeramic",
       [](Session& s) {
         grid(s, PERISTEP_SCENE_GLASS_CERAMIC, 51, 26);  // h = 16 um; pure glass breaks from about 0.15 um
         REQUIRE(s.setFloat64(PERISTEP_VR_LX, {800e-6}) == fmi3OK);
         REQUIRE(s.setFloat64(PERISTEP_VR_LY, {400e-6}) == fmi3OK);
         REQUIRE(s.setFloat64(PERISTEP_VR_POISSON_RATIO, {0.25}) == fmi3OK);
         REQUIRE(s.setFloat64(PERISTEP_VR_CRYSTAL_FRACTION, {0.0}) == fmi3OK);
       },
       0.25, PERISTEP_VR_LOAD_DISPLACEMENT},
      // 001's Plexiglass square at eps = 8 mm, h = eps/2, at its step 0.004 us.
      {"plexiglassCrack", [](Session& s) { dynamic(s, PERISTEP_SCENE_PLEXIGLASS_CRACK, 25, 25, 0.1, 0.1, 2, 0); }, 2e-6,
       PERISTEP_VR_LOAD_FACTOR},
      // 001's beam at h = 3.125 mm with an internal step far below the stability limit but above 001's.
      {"bendingOneNotch",
       [](Session& s) { dynamic(s, PERISTEP_SCENE_BENDING_ONE_NOTCH, 80, 16, 0.25, 0.05, 3, 0.05e-6); }, 10e-6,
       PERISTEP_VR_LOAD_FACTOR},
      {"bendingTwoNotches",
       [](Session& s) { dynamic(s, PERISTEP_SCENE_BENDING_TWO_NOTCHES, 80, 16, 0.25, 0.05, 3, 0.05e-6); }, 10e-6,
       PERISTEP_VR_LOAD_FACTOR},
  };
  for (const Scene& scene : scenes) {
    const auto base = run(scene, kBase, all);
    for (std::size_t input = 0; input < 2; ++input) {
      INFO(scene.name << ", changing input vr " << kInputs[input]);
      double second[2] = {kBase[0], kBase[1]};
      second[input] = kChanged[input];
      const auto changed = run(scene, second, all);
      std::size_t differing = 0;
      for (std::size_t k = 0; k < all.size(); ++k) {
        if (changed[k] == base[k]) continue;
        ++differing;
        const Output& o = all[k];
        INFO(o.name << " changed");
        CHECK((!o.dependencies ||
               std::find(o.dependencies->begin(), o.dependencies->end(), kInputs[input]) != o.dependencies->end()));
      }
      if (kInputs[input] == scene.drivenBy) CHECK(differing > 0);  // the change reaches the outputs
    }
  }
}
