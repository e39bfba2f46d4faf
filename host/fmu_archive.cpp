#include "fmu_archive.hpp"

#include <zip.h>

#include <cstdlib>
#include <fstream>
#include <memory>
#include <system_error>
#include <vector>

#include "host_errors.hpp"

namespace peristep::host {

namespace fs = std::filesystem;

namespace {

struct ZipCloser {
  void operator()(zip_t* z) const { zip_discard(z); }  // read-only: nothing to write back
};
struct ZipFileCloser {
  void operator()(zip_file_t* f) const { zip_fclose(f); }
};

fs::path makeTemporaryDirectory() {
  const char* base = std::getenv("TMPDIR");
  std::string pattern = (fs::path(base && *base ? base : "/tmp") / "peristep-fmu-XXXXXX").string();
  if (!mkdtemp(pattern.data())) throw RunError("cannot create a temporary directory for the FMU in " + pattern);
  return pattern;
}

// An entry name is unpacked only if it stays inside the target directory (no "..", no absolute path).
bool isSafeEntry(const std::string& name) {
  const fs::path p(name);
  if (p.is_absolute() || name.empty()) return false;
  for (const auto& part : p)
    if (part == "..") return false;
  return true;
}

void unpack(const fs::path& archive, const fs::path& target) {
  int code = 0;
  std::unique_ptr<zip_t, ZipCloser> zip(zip_open(archive.c_str(), ZIP_RDONLY, &code));
  if (!zip) {
    zip_error_t error;
    zip_error_init_with_code(&error, code);
    const std::string what = zip_error_strerror(&error);
    zip_error_fini(&error);
    throw InputError(archive.string() + ": cannot open the FMU archive: " + what);
  }
  const zip_int64_t n = zip_get_num_entries(zip.get(), 0);
  std::vector<char> buffer(1 << 16);
  for (zip_int64_t i = 0; i < n; ++i) {
    const char* raw = zip_get_name(zip.get(), static_cast<zip_uint64_t>(i), 0);
    const std::string name = raw ? raw : "";
    if (!isSafeEntry(name)) throw InputError(archive.string() + ": unsafe entry name \"" + name + "\" in the FMU");
    const fs::path out = target / name;
    if (name.back() == '/') {
      fs::create_directories(out);
      continue;
    }
    fs::create_directories(out.parent_path());
    std::unique_ptr<zip_file_t, ZipFileCloser> in(zip_fopen_index(zip.get(), static_cast<zip_uint64_t>(i), 0));
    if (!in) throw InputError(archive.string() + ": cannot read " + name + ": " + zip_strerror(zip.get()));
    std::ofstream file(out, std::ios::binary);
    for (zip_int64_t got; (got = zip_fread(in.get(), buffer.data(), buffer.size())) > 0;)
      file.write(buffer.data(), got);
    if (!file) throw RunError("cannot unpack " + name + " to " + out.string());
  }
}

}  // namespace

FmuArchive::FmuArchive(const fs::path& fmuOrDirectory) : source_(fmuOrDirectory) {
  std::error_code ec;
  if (fs::is_directory(fmuOrDirectory, ec)) {
    root_ = fs::absolute(fmuOrDirectory);
    return;
  }
  if (!fs::exists(fmuOrDirectory, ec)) throw InputError(fmuOrDirectory.string() + ": no such FMU (file or directory)");
  root_ = makeTemporaryDirectory();
  temporary_ = true;
  try {
    unpack(fmuOrDirectory, root_);
  } catch (...) {
    fs::remove_all(root_, ec);
    throw;
  }
}

FmuArchive::~FmuArchive() {
  std::error_code ec;  // best effort: a destructor must not throw
  if (temporary_) fs::remove_all(root_, ec);
}

fs::path FmuArchive::binaryFile(const std::string& modelIdentifier) const {
  return root_ / "binaries" / "x86_64-linux" / (modelIdentifier + ".so");
}

std::string FmuArchive::resourcePath() const {
  const fs::path resources = root_ / "resources";
  std::error_code ec;
  return fs::is_directory(resources, ec) ? resources.string() + "/" : std::string();
}

}  // namespace peristep::host
