#pragma once
// Finished samples of a study, one small file each in a directory beside the result file, named by a
// hash of everything that defines the sample (the component binary, its instantiation token, parameters
// with this sample's coordinates, loading).
// A file is written under a temporary name and renamed, so an interrupted study leaves only whole
// samples; restarting the same command finds them and recomputes nothing. A dead run's temporaries are
// removed when the store is next opened; every file ends in a checksum, and a damaged one is recomputed
// with a warning. Samples shared by two rules or levels (nested rules, the centre node) are computed
// once. Processes that share the directory (MPI ranks, batch-array shards) share the samples.
// A sample the component refused (fmi3Error) is kept as a text file with the message
// (sample-<key>.failed): it is finished too, not retried on restart; delete the file to retry it.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace peristep::host {

// The outputs a sample keeps: Float64 scalars and fields after its last load increment.
struct SampleRecord {
  std::vector<double> scalars;
  std::vector<std::vector<double>> fields;
  double seconds = 0;  // wall time of the sample when it was computed
};

class SampleStore {
 public:
  explicit SampleStore(std::filesystem::path directory);  // created when missing; throws RunError

  // Stable 64-bit FNV-1a of the text that defines a sample.
  static std::uint64_t key(const std::string& definition);
  // FNV-1a of a file's bytes, in hex: part of every key, so that samples computed by another build of
  // the component are not taken for this one's.
  static std::string fileDigest(const std::filesystem::path& file);
  // The record, or nothing when it is missing or does not match the expected shape (then recomputed).
  // Without fields, the fields are checked but not kept (the record's fields are empty).
  std::optional<SampleRecord> load(std::uint64_t key, std::size_t scalars, const std::vector<std::uint64_t>& fieldSizes,
                                   bool withFields = true) const;
  void save(std::uint64_t key, const SampleRecord& record) const;
  // The component's message for a failed sample, or nothing.
  std::optional<std::string> failure(std::uint64_t key) const;
  void saveFailure(std::uint64_t key, const std::string& message) const;
  const std::filesystem::path& directory() const { return dir_; }

 private:
  std::filesystem::path file(std::uint64_t key) const;
  std::filesystem::path failureFile(std::uint64_t key) const;  // sample-<key>.failed
  void removeStaleTemporaries() const;
  std::filesystem::path dir_;
};

}  // namespace peristep::host
