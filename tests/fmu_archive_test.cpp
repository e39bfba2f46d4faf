// PeriStep.fmu unpacked with libzip: the model description, the binary and the documentation,
// byte for byte the files they were packed from, and beside them only the shared libraries the
// binary bundles and their licences (fmu_self_contained_test.sh checks that those suffice); the
// documentation lists every variable of the packed model description.
#include <zip.h>

#include <catch2/catch.hpp>
#include <fstream>
#include <map>
#include <sstream>

#include "model_description_xml.hpp"

namespace {

std::string readFile(const char* path) {
  std::ifstream in(path, std::ios::binary);
  REQUIRE(in);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Every entry of the archive: name -> content.
std::map<std::string, std::string> unpack(const char* path) {
  int error = 0;
  zip_t* archive = zip_open(path, ZIP_RDONLY | ZIP_CHECKCONS, &error);
  REQUIRE(archive != nullptr);
  std::map<std::string, std::string> entries;
  const zip_int64_t n = zip_get_num_entries(archive, 0);
  for (zip_int64_t k = 0; k < n; ++k) {
    zip_stat_t st;
    REQUIRE(zip_stat_index(archive, static_cast<zip_uint64_t>(k), 0, &st) == 0);
    zip_file_t* file = zip_fopen_index(archive, static_cast<zip_uint64_t>(k), 0);
    REQUIRE(file != nullptr);
    std::string content(st.size, '\0');
    const zip_int64_t read = zip_fread(file, content.data(), st.size);
    zip_fclose(file);
    REQUIRE(read == static_cast<zip_int64_t>(st.size));
    entries.emplace(st.name, std::move(content));
  }
  zip_close(archive);
  return entries;
}

}  // namespace

TEST_CASE("PeriStep.fmu holds the model description, the binary, the documentation and the resources", "[fmu]") {
  const auto entries = unpack(PERISTEP_FMU_ARCHIVE);
  const std::string bundled = "binaries/x86_64-linux/lib", licenses = "documentation/licenses/";
  for (const auto& [name, content] : entries) {
    if (name.starts_with(bundled)) {
      CHECK(content.substr(0, 4) == "\x7f" "ELF");
    } else if (!name.starts_with(licenses)) {
      CHECK((name == "modelDescription.xml" || name == "binaries/x86_64-linux/PeriStep.so" ||
             name == "documentation/index.html" || name == "documentation/input_loadFactor.csv" ||
             name == "resources/md_fracture_samples.bin"));
    }
  }
  REQUIRE(entries.count(licenses + "license.txt") == 1);
  REQUIRE(entries.count("modelDescription.xml") == 1);
  REQUIRE(entries.count("binaries/x86_64-linux/PeriStep.so") == 1);
  REQUIRE(entries.count("documentation/index.html") == 1);
  CHECK(entries.at("modelDescription.xml") == readFile(PERISTEP_GENERATED_MODEL_DESCRIPTION));
  CHECK(entries.at("binaries/x86_64-linux/PeriStep.so") == readFile(PERISTEP_SO_PATH));
  CHECK(entries.at("documentation/index.html") == readFile(PERISTEP_FMU_DOCUMENTATION));
  CHECK(entries.at("binaries/x86_64-linux/PeriStep.so").substr(0, 4) == "\x7f" "ELF");
  // Scene learnedFracture's model and MD frames, as the build wrote them.
  REQUIRE(entries.count("resources/md_fracture_samples.bin") == 1);
  CHECK(entries.at("resources/md_fracture_samples.bin") == readFile(PERISTEP_RESOURCES_PATH "md_fracture_samples.bin"));
}

TEST_CASE("the FMU's documentation/index.html lists every variable of its model description", "[fmu]") {
  const auto entries = unpack(PERISTEP_FMU_ARCHIVE);
  REQUIRE(entries.count("documentation/index.html") == 1);
  const std::string& html = entries.at("documentation/index.html");
  const XmlDocument doc(entries.at("modelDescription.xml"));
  std::size_t listed = 0;
  for (xmlNodePtr v : children(firstChild(doc.root(), "ModelVariables"))) {
    // The variable's row: its name, then its value reference, then its type (the XML element's name).
    const std::string name = attribute(v, "name");
    const std::string row = "<tr id=\"var-" + name + "\"><td><code>" + name + "</code></td><td>" +
                            attribute(v, "valueReference") + "</td><td>" + elementName(v);
    INFO(row);
    CHECK(html.find(row) != std::string::npos);
    ++listed;
  }
  CHECK(listed > 40);
  // The importers' example input: a CSV whose columns are time and an input of the model description,
  // spanning the default experiment; the page points at it.
  REQUIRE(entries.count("documentation/input_loadFactor.csv") == 1);
  const std::string& csv = entries.at("documentation/input_loadFactor.csv");
  CHECK(csv.rfind("time,loadFactor\n0,0\n", 0) == 0);
  xmlNodePtr experiment = firstChild(doc.root(), "DefaultExperiment");
  REQUIRE(experiment != nullptr);
  CHECK(csv.find("\n" + attribute(experiment, "stopTime") + ",") != std::string::npos);
  bool loadIsInput = false;
  for (xmlNodePtr v : children(firstChild(doc.root(), "ModelVariables")))
    loadIsInput |= attribute(v, "name") == "loadFactor" && attribute(v, "causality") == "input";
  CHECK(loadIsInput);
  CHECK(html.find("fmusim --input-file input_loadFactor.csv") != std::string::npos);
  // The page names no file the archive lacks (the C header stays in the source tree).
  CHECK(html.find(".h<") == std::string::npos);
  CHECK(html.find("peristep.h") == std::string::npos);
}
