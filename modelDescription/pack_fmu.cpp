// Packs an FMU archive (a zip, FMI 3.0 Sec. 2.5): every argument after the output names one
// entry as <path in archive>=<file on disk>, or a folder as <folder in archive>/=<directory on disk>
// (every file below it, in name order, so that the archive does not depend on the file system).
//
//   pack_fmu PeriStep.fmu modelDescription.xml=build/modelDescription.xml
//            binaries/x86_64-linux/PeriStep.so=build/component/fmi/PeriStep.so
//            binaries/x86_64-linux/=build/fmu_bundle/binaries/x86_64-linux ...
#include <zip.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace {

int fail(zip_t* archive, const std::string& what) {
  std::fprintf(stderr, "pack_fmu: %s: %s\n", what.c_str(), archive ? zip_strerror(archive) : "");
  if (archive) zip_discard(archive);
  return 1;
}

// The (entry, file) pairs of one argument: the file itself, or every file below a directory.
std::vector<std::pair<std::string, std::string>> entriesOf(const std::string& entry, const std::string& file) {
  namespace fs = std::filesystem;
  if (entry.back() != '/') return {{entry, file}};
  std::vector<std::pair<std::string, std::string>> entries;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(file, ec), end; !ec && it != end; it.increment(ec))
    if (it->is_regular_file()) entries.emplace_back(entry + fs::relative(it->path(), file).generic_string(),
                                                    it->path().string());
  if (ec) entries.clear();  // an unreadable directory: reported by the caller as empty
  std::sort(entries.begin(), entries.end());
  return entries;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s <archive.fmu> <entry>=<file>...\n", argv[0]);
    return 2;
  }
  int error = 0;
  zip_t* archive = zip_open(argv[1], ZIP_CREATE | ZIP_TRUNCATE, &error);
  if (!archive) {
    std::fprintf(stderr, "pack_fmu: cannot create %s (libzip error %d)\n", argv[1], error);
    return 1;
  }
  for (int k = 2; k < argc; ++k) {
    const std::string spec = argv[k];
    const auto eq = spec.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == spec.size())
      return fail(archive, "expected <entry>=<file>, got '" + spec + "'");
    const auto entries = entriesOf(spec.substr(0, eq), spec.substr(eq + 1));
    if (entries.empty()) return fail(archive, "no files to pack in " + spec.substr(eq + 1));
    for (const auto& [entry, file] : entries) {
      zip_source_t* source = zip_source_file(archive, file.c_str(), 0, -1 /* to the end */);
      if (!source) return fail(archive, "cannot read " + file);
      const zip_int64_t index = zip_file_add(archive, entry.c_str(), source, ZIP_FL_ENC_UTF_8);
      if (index < 0) {
        zip_source_free(source);
        return fail(archive, "cannot add " + entry);
      }
      if (zip_set_file_compression(archive, static_cast<zip_uint64_t>(index), ZIP_CM_DEFLATE, 9) < 0)
        return fail(archive, "cannot compress " + entry);
    }
  }
  // zip_close writes to a temporary file and renames it: a failed run leaves no half archive.
  if (zip_close(archive) < 0) return fail(archive, std::string("cannot write ") + argv[1]);
  return 0;
}
