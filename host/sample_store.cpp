#include "sample_store.hpp"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string_view>

#include "atomic_file.hpp"
#include "host_errors.hpp"

namespace peristep::host {

namespace {

// Format 2: the bytes after the magic end in the FNV-1a 64 of everything before them.
constexpr char kMagic[8] = {'P', 'S', 'S', 'A', 'M', 'P', 'L', '2'};

template <class T>
void put(std::string& out, const T& v) {
  out.append(reinterpret_cast<const char*>(&v), sizeof v);
}

void putVector(std::string& out, const std::vector<double>& v) {
  put(out, static_cast<std::uint64_t>(v.size()));
  out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(double));
}

// Reads a record's payload front to back; every read fails once the bytes run out.
struct Reader {
  std::string_view bytes;
  template <class T>
  bool get(T& v) {
    if (bytes.size() < sizeof v) return false;
    std::memcpy(&v, bytes.data(), sizeof v);
    bytes.remove_prefix(sizeof v);
    return true;
  }
  // keep = false: the vector is checked and passed over, `v` left empty.
  bool getVector(std::vector<double>& v, std::uint64_t expected, bool keep = true) {
    std::uint64_t n = 0;
    if (!get(n) || n != expected || bytes.size() / sizeof(double) < n) return false;
    if (keep) {
      v.resize(n);
      std::memcpy(v.data(), bytes.data(), n * sizeof(double));
    }
    bytes.remove_prefix(n * sizeof(double));
    return true;
  }
};

}  // namespace

SampleStore::SampleStore(std::filesystem::path directory) : dir_(std::move(directory)) {
  std::error_code ec;
  std::filesystem::create_directories(dir_, ec);
  if (ec) throw RunError("cannot create the sample directory " + dir_.string() + ": " + ec.message());
  removeStaleTemporaries();
}

// A temporary is "<final>.<host>.<pid>.tmp": one of this host whose process has ended was left by a run
// that died (or a full disk) and is removed; other hosts' and live processes' are theirs.
void SampleStore::removeStaleTemporaries() const {
  std::string prefix(1, '.');
  prefix += hostName();
  prefix += '.';
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir_, ec)) {
    const std::string name = entry.path().filename().string();
    if (entry.path().extension() != ".tmp") continue;
    const std::size_t at = name.rfind(prefix);
    if (at == std::string::npos) continue;
    const std::string pid = name.substr(at + prefix.size(), name.size() - 4 - at - prefix.size());
    if (pid.empty() || pid.find_first_not_of("0123456789") != std::string::npos) continue;
    if (::kill(static_cast<pid_t>(std::stol(pid)), 0) != 0 && errno == ESRCH) std::filesystem::remove(entry.path(), ec);
  }
}

std::uint64_t SampleStore::key(const std::string& definition) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : definition) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

std::string SampleStore::fileDigest(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw RunError("cannot read " + file.string());
  std::ostringstream bytes;
  bytes << in.rdbuf();
  char hex[20];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(key(bytes.str())));
  return hex;
}

std::filesystem::path SampleStore::file(std::uint64_t key) const {
  char name[40];
  std::snprintf(name, sizeof name, "sample-%016llx.bin", static_cast<unsigned long long>(key));
  return dir_ / name;
}

std::optional<SampleRecord> SampleStore::load(std::uint64_t key, std::size_t scalars,
                                              const std::vector<std::uint64_t>& fieldSizes, bool withFields) const {
  std::ifstream in(file(key), std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream content;
  content << in.rdbuf();
  const std::string bytes = content.str();
  std::uint64_t stored = 0;
  if (bytes.size() < sizeof kMagic + sizeof stored || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
    return std::nullopt;  // another format: recomputed
  const std::string_view payload(bytes.data(), bytes.size() - sizeof stored);
  std::memcpy(&stored, bytes.data() + payload.size(), sizeof stored);
  if (SampleStore::key(std::string(payload)) != stored) {
    std::cerr << "peristep: warning: " << file(key).string()
              << " is damaged (checksum mismatch); the sample is computed again\n";
    return std::nullopt;
  }
  Reader r{payload.substr(sizeof kMagic)};
  SampleRecord record;
  std::uint64_t nFields = 0;
  if (!r.get(record.seconds) || !r.getVector(record.scalars, scalars) || !r.get(nFields) ||
      nFields != fieldSizes.size())
    return std::nullopt;
  record.fields.resize(withFields ? nFields : 0);
  std::vector<double> passed;
  for (std::size_t i = 0; i < nFields; ++i)
    if (!r.getVector(withFields ? record.fields[i] : passed, fieldSizes[i], withFields)) return std::nullopt;
  if (!r.bytes.empty()) return std::nullopt;
  return record;
}


void SampleStore::save(std::uint64_t key, const SampleRecord& record) const {
  std::string bytes(kMagic, sizeof kMagic);
  put(bytes, record.seconds);
  putVector(bytes, record.scalars);
  put(bytes, static_cast<std::uint64_t>(record.fields.size()));
  for (const auto& f : record.fields) putVector(bytes, f);
  put(bytes, SampleStore::key(bytes));
  writeFileAtomically(file(key), bytes);
}

std::filesystem::path SampleStore::failureFile(std::uint64_t key) const {
  return std::filesystem::path(file(key)).replace_extension(".failed");
}

std::optional<std::string> SampleStore::failure(std::uint64_t key) const {
  std::ifstream in(failureFile(key));
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void SampleStore::saveFailure(std::uint64_t key, const std::string& message) const {
  writeFileAtomically(failureFile(key), message);
}

}  // namespace peristep::host
