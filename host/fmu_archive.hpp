#pragma once
// An FMU opened for use: a .fmu archive unpacked (libzip) into a private temporary directory that
// is removed again on destruction, or an already unpacked directory used in place.
#include <filesystem>
#include <string>

namespace peristep::host {

class FmuArchive {
 public:
  // Throws InputError when the path does not exist or is not a readable zip archive.
  explicit FmuArchive(const std::filesystem::path& fmuOrDirectory);
  ~FmuArchive();
  FmuArchive(const FmuArchive&) = delete;
  FmuArchive& operator=(const FmuArchive&) = delete;

  const std::filesystem::path& source() const { return source_; }
  const std::filesystem::path& root() const { return root_; }
  std::filesystem::path modelDescriptionFile() const { return root_ / "modelDescription.xml"; }
  // binaries/x86_64-linux/<modelIdentifier>.so (FMI 3.0 platform tuple of this host).
  std::filesystem::path binaryFile(const std::string& modelIdentifier) const;
  // The resourcePath argument of fmi3Instantiate*: absolute, with a trailing separator; empty when
  // the FMU has no resources/ directory.
  std::string resourcePath() const;

 private:
  std::filesystem::path source_, root_;
  bool temporary_ = false;
};

}  // namespace peristep::host
