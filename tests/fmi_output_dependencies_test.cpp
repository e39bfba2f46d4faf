// The <Output dependencies> of modelDescription.xml are true to the code: in every scene, an output that
// changes when one input changes lists that input (FMI 3.0.2 Sec. 2.4.8: an unknown depends on exactly
// the knowns it lists; no attribute means all). Each scene runs on a coarse grid through the C ABI, two
// steps at the base inputs and, in fresh instances, two steps with one input changed in the second; the
// outputs after the second step are compared.
#include <catch2/catch.hpp>
#include <map>
#include <optional>
#include <sstream>

#include "fmi_abi_support.hpp"
#include "fmi_scene_setups.hpp"
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
  std::int64_t id;
  double step;                  // communication step [s]
  fmi3ValueReference drivenBy;  // the input that must change some output
};

const fmi3ValueReference kInputs[] = {PERISTEP_VR_LOAD_FACTOR, PERISTEP_VR_LOAD_DISPLACEMENT};
constexpr double kBase[] = {1.0, 0.05e-6}, kChanged[] = {0.5, 0.25e-6};  // loadFactor, loadDisplacement [m]

void setInputs(Session& s, const double (&values)[2]) {
  REQUIRE(s.fmu.fmi3SetFloat64(s.instance, kInputs, 2, values, 2) == fmi3OK);
}

// The outputs after two steps, the first at the base inputs, the second at `second`, in a fresh instance.
std::vector<std::vector<double>> run(const Scene& scene, const double (&second)[2], const std::vector<Output>& all) {
  Session s;
  setUpCoarseScene(s, scene.id);
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

}  // namespace

TEST_CASE("every output lists the inputs it depends on in every scene", "[modelDescription][dependencies]") {
  const std::vector<Output> all = outputs();
  REQUIRE(all.size() > 10);
  const std::vector<Scene> scenes{
      {"smooth", PERISTEP_SCENE_SMOOTH, 0.25, PERISTEP_VR_LOAD_FACTOR},
      {"composite", PERISTEP_SCENE_COMPOSITE, 0.25, PERISTEP_VR_LOAD_FACTOR},
      {"interfaceCrack", PERISTEP_SCENE_INTERFACE_CRACK, 0.25, PERISTEP_VR_LOAD_FACTOR},
      {"klPlate", PERISTEP_SCENE_KL_PLATE, 0.25, PERISTEP_VR_LOAD_FACTOR},
      {"glassCeramic", PERISTEP_SCENE_GLASS_CERAMIC, 0.25, PERISTEP_VR_LOAD_DISPLACEMENT},
      {"plexiglassCrack", PERISTEP_SCENE_PLEXIGLASS_CRACK, 2e-6, PERISTEP_VR_LOAD_FACTOR},
      {"bendingOneNotch", PERISTEP_SCENE_BENDING_ONE_NOTCH, 2e-6, PERISTEP_VR_LOAD_FACTOR},
      {"bendingTwoNotches", PERISTEP_SCENE_BENDING_TWO_NOTCHES, 2e-6, PERISTEP_VR_LOAD_FACTOR},
      {"specimen", PERISTEP_SCENE_SPECIMEN, 0.25, PERISTEP_VR_LOAD_FACTOR},
      {"gamutBar", PERISTEP_SCENE_GAMUT_BAR, 0.25, PERISTEP_VR_LOAD_FACTOR},
      {"learnedFracture", PERISTEP_SCENE_LEARNED_FRACTURE, 4.95e-14, PERISTEP_VR_TIME},  // driven by its frames
      {"patchTest", PERISTEP_SCENE_PATCH_TEST, 0.25, PERISTEP_VR_LOAD_FACTOR},
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
