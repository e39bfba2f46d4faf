// The host knows the component only through its C ABI: no source under host/ may include anything
// from component/. Quoted includes must resolve inside host/, api/ or hdf5/ (the HDF5 layer that the host
// and the learning library share, which knows neither); bracketed ones must not name a component header.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

const fs::path kSource = PERISTEP_SOURCE_DIR;

bool existsInside(const fs::path& dir, const fs::path& candidate) {
  const fs::path resolved = fs::weakly_canonical(candidate);
  return fs::exists(resolved) && resolved.string().starts_with(fs::weakly_canonical(dir).string() + "/");
}

// The offending include lines of one file ("file:line: text"), empty when the file is clean.
std::vector<std::string> foreignIncludes(const fs::path& file, std::istream& text) {
  static const std::regex include(R"(^\s*#\s*include\s*([<"])([^>"]+)[>"])");
  std::vector<std::string> bad;
  std::string line;
  for (int number = 1; std::getline(text, line); ++number) {
    std::smatch m;
    if (!std::regex_search(line, m, include)) continue;
    const std::string name = m[2];
    bool ok;
    if (m[1] == "\"") {
      ok = existsInside(kSource / "host", file.parent_path() / name) || existsInside(kSource / "api", kSource / "api" / name) ||
           existsInside(kSource / "hdf5", kSource / "hdf5" / name);
    } else {
      ok = !fs::is_regular_file(kSource / "component" / name) && name.find("component/") == std::string::npos;
    }
    if (!ok) bad.push_back(file.string() + ":" + std::to_string(number) + ": " + line);
  }
  return bad;
}

}  // namespace

TEST_CASE("host sources include nothing from component/", "[host][include]") {
  std::vector<std::string> bad;
  int files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(kSource / "host")) {
    const std::string ext = entry.path().extension().string();
    if (ext != ".cpp" && ext != ".hpp" && ext != ".in" && ext != ".h") continue;
    std::ifstream in(entry.path());
    for (auto& b : foreignIncludes(entry.path(), in)) bad.push_back(b);
    ++files;
  }
  CHECK(files > 10);
  INFO("offending includes:\n" << [&] {
    std::string all;
    for (const auto& b : bad) all += b + "\n";
    return all;
  }());
  CHECK(bad.empty());
}

TEST_CASE("the include check catches component headers", "[host][include]") {
  const fs::path file = kSource / "host" / "simulation.cpp";
  std::istringstream quoted("#include \"scenes/scene_model.hpp\"\n#include \"../component/core/errors.hpp\"\n");
  CHECK(foreignIncludes(file, quoted).size() == 2);
  std::istringstream bracketed("#include <scenes/scene_model.hpp>\n#include <vector>\n#include \"fmi3Functions.h\"\n");
  CHECK(foreignIncludes(file, bracketed).size() == 1);
  std::istringstream shared("#include \"hdf5_io.hpp\"\n");
  CHECK(foreignIncludes(file, shared).empty());
}
