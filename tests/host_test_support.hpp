#pragma once
// Helpers shared by the host tests: a private temporary directory, running the `peristep` binary
// with its output captured, and reading HDF5 datasets back with the C API.
#include <fcntl.h>
#include <hdf5.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace host_test {

namespace fs = std::filesystem;

class TempDir {
 public:
  TempDir() {
    std::string pattern = (fs::temp_directory_path() / "peristep-host-test-XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
    path_ = pattern;
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const fs::path& path() const { return path_; }
  fs::path operator/(const std::string& name) const { return path_ / name; }

 private:
  fs::path path_;
};

// An environment variable set for a scope (children started in it inherit it), then restored.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const std::string& value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    setenv(name, value.c_str(), 1);
  }
  ~ScopedEnv() { old_ ? setenv(name_, old_->c_str(), 1) : unsetenv(name_); }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  const char* name_;
  std::optional<std::string> old_;
};

// A killed host cannot remove the FMU it unpacked: tests that kill one point its TMPDIR here.
inline fs::path privateTmp(const TempDir& dir) {
  fs::create_directories(dir / "tmp");
  return dir / "tmp";
}

inline std::string readText(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void writeText(const fs::path& file, const std::string& text) { std::ofstream(file, std::ios::binary) << text; }

// scenes/<name> with its nx and ny lines set to n (a small grid for a quick study).
inline std::string sceneOnGrid(const std::string& name, int n) {
  std::istringstream in(readText(fs::path(PERISTEP_SOURCE_DIR) / "scenes" / name));
  std::string out;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("nx =", 0) == 0) line = "nx = " + std::to_string(n);
    if (line.rfind("ny =", 0) == 0) line = "ny = " + std::to_string(n);
    out += line + '\n';
  }
  return out;
}

struct ProcessResult {
  int exitCode = -1;
  std::string out, err;
};

// Runs a program in `cwd` with stdout and stderr captured (through files: no pipe can fill up).
inline ProcessResult runProcess(const std::vector<std::string>& args, const fs::path& cwd) {
  const fs::path outFile = cwd / ".stdout", errFile = cwd / ".stderr";
  const pid_t pid = fork();
  if (pid == 0) {
    const int out = open(outFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = open(errFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (out < 0 || err < 0 || dup2(out, 1) < 0 || dup2(err, 2) < 0 || chdir(cwd.c_str()) != 0) _exit(127);
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    _exit(127);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  ProcessResult r;
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = readText(outFile);
  r.err = readText(errFile);
  fs::remove(outFile);
  fs::remove(errFile);
  return r;
}

inline std::size_t lineCount(const std::string& s) {
  std::size_t n = 0;
  for (char c : s) n += c == '\n';
  return n + (!s.empty() && s.back() != '\n');
}

// A dataset's shape and values (as doubles), or an empty shape when it does not exist.
struct Dataset {
  std::vector<hsize_t> shape;
  std::vector<double> values;
};

inline Dataset readDataset(hid_t file, const std::string& path) {
  Dataset d;
  if (H5Lexists(file, path.c_str(), H5P_DEFAULT) <= 0) return d;
  const hid_t set = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  const hid_t space = H5Dget_space(set);
  d.shape.resize(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space)));
  H5Sget_simple_extent_dims(space, d.shape.data(), nullptr);
  hsize_t n = 1;
  for (hsize_t e : d.shape) n *= e;
  d.values.resize(n);
  if (n > 0) H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, d.values.data());
  H5Sclose(space);
  H5Dclose(set);
  return d;
}

// Opens read-only; the caller closes with H5Fclose. Negative when the file is not HDF5.
inline hid_t openHdf5(const fs::path& file) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  return H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
}

}  // namespace host_test
