#include "sample_store.hpp"

#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include "host_errors.hpp"

namespace peristep::host {

namespace {

constexpr char kMagic[8] = {'P', 'S', 'S', 'A', 'M', 'P', 'L', '1'};

template <class T>
void put(std::ofstream& out, const T& v) {
  out.write(reinterpret_cast<const char*>(&v), sizeof v);
}

void putVector(std::ofstream& out, const std::vector<double>& v) {
  put(out, static_cast<std::uint64_t>(v.size()));
  out.write(reinterpret_cast<const char*>(v.data()), static_cast<std::streamsize>(v.size() * sizeof(double)));
}

template <class T>
bool get(std::ifstream& in, T& v) {
  return static_cast<bool>(in.read(reinterpret_cast<char*>(&v), sizeof v));
}

bool getVector(std::ifstream& in, std::vector<double>& v, std::uint64_t expected) {
  std::uint64_t n = 0;
  if (!get(in, n) || n != expected) return false;
  v.resize(n);
  return static_cast<bool>(in.read(reinterpret_cast<char*>(v.data()), static_cast<std::streamsize>(n * sizeof(double))));
}

}  // namespace

SampleStore::SampleStore(std::filesystem::path directory) : dir_(std::move(directory)) {
  std::error_code ec;
  std::filesystem::create_directories(dir_, ec);
  if (ec) throw RunError("cannot create the sample directory " + dir_.string() + ": " + ec.message());
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
                                              const std::vector<std::uint64_t>& fieldSizes) const {
  std::ifstream in(file(key), std::ios::binary);
  if (!in) return std::nullopt;
  char magic[8];
  if (!in.read(magic, sizeof magic) || std::memcmp(magic, kMagic, sizeof magic) != 0) return std::nullopt;
  SampleRecord r;
  std::uint64_t nFields = 0;
  if (!get(in, r.seconds) || !getVector(in, r.scalars, scalars) || !get(in, nFields) || nFields != fieldSizes.size())
    return std::nullopt;
  r.fields.resize(nFields);
  for (std::size_t i = 0; i < nFields; ++i)
    if (!getVector(in, r.fields[i], fieldSizes[i])) return std::nullopt;
  return r;
}

namespace {

// Writes under a temporary name unique to the process, host and pid (two processes may finish the same
// sample), and renames: a reader sees the old state or the whole file.
template <class Write>
void writeAtomically(const std::filesystem::path& final, Write write) {
  char host[256] = "";
  ::gethostname(host, sizeof host - 1);
  const std::filesystem::path temporary = final.string() + "." + host + "." + std::to_string(::getpid()) + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    write(out);
    out.flush();
    if (!out) throw RunError("cannot write " + temporary.string());
  }
  std::error_code ec;
  std::filesystem::rename(temporary, final, ec);
  if (ec) throw RunError("cannot rename " + temporary.string() + ": " + ec.message());
}

}  // namespace

void SampleStore::save(std::uint64_t key, const SampleRecord& record) const {
  writeAtomically(file(key), [&](std::ofstream& out) {
    out.write(kMagic, sizeof kMagic);
    put(out, record.seconds);
    putVector(out, record.scalars);
    put(out, static_cast<std::uint64_t>(record.fields.size()));
    for (const auto& f : record.fields) putVector(out, f);
  });
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
  writeAtomically(failureFile(key), [&](std::ofstream& out) { out << message; });
}

}  // namespace peristep::host
