#pragma once
// PeriStep's layer over the HDF5 C API, used by the host's result files and the learning library's data
// files: identifiers owned by handles (closed on every path, errors included), failures thrown as
// hdf5::Error with a one-line message ("HDF5: cannot <what>"), attributes, plain (non-extendible) datasets
// of doubles, and the names below a group. What only one side writes (the host's extendible series and
// virtual views) stays with that side, built on Handle and check().
#include <hdf5.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace peristep::hdf5 {

// Every failure of this layer. Callers turn it into their own kind of error where it matters.
struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Owns one HDF5 identifier and closes it with the function that matches its kind.
class Handle {
 public:
  using Closer = herr_t (*)(hid_t);
  Handle() = default;
  // Throws Error("HDF5: cannot <what>") for a negative id.
  Handle(hid_t id, Closer closer, const std::string& what);
  ~Handle() { reset(); }
  Handle(Handle&& other) noexcept : id_(other.id_), closer_(other.closer_) { other.id_ = -1; }
  Handle& operator=(Handle&& other) noexcept;
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;

  operator hid_t() const { return id_; }
  // Closes now and throws Error when HDF5 reports a failure (a file's last writes happen here).
  void close(const std::string& what);

 private:
  void reset();
  hid_t id_ = -1;
  Closer closer_ = nullptr;
};

// Throws Error("HDF5: cannot <what>") for a negative status.
void check(herr_t status, const std::string& what);

// Files. Both switch off HDF5's own error-stack printing: its failures reach the caller as Error.
Handle createFile(const std::string& path);  // created, or truncated
Handle openFile(const std::string& path);    // read-only

// A group, created with its intermediate groups, or opened.
Handle createGroup(hid_t parent, const std::string& path);
Handle openGroup(hid_t parent, const std::string& path);

// Attributes. A one-element vector is stored as a scalar attribute.
void writeString(hid_t object, const std::string& name, const std::string& value);
void writeNumbers(hid_t object, const std::string& name, const std::vector<double>& values);
void writeNumbers(hid_t object, const std::string& name, const std::vector<std::int64_t>& values);
void writeNumbers(hid_t object, const std::string& name, const std::vector<std::uint64_t>& values);
// A scalar numeric attribute, converted to double.
double readDouble(hid_t object, const std::string& name);

// A dataset of doubles with the given shape (empty shape: a scalar), written whole; returned open.
Handle writeDataset(hid_t parent, const std::string& name, const std::vector<std::uint64_t>& shape, const double* data);
struct Doubles {
  std::vector<std::uint64_t> shape;
  std::vector<double> values;  // row-major
};
Doubles readDataset(hid_t parent, const std::string& name);

// The names of an object's attributes and of a group's links, in name order.
std::vector<std::string> attributeNames(hid_t object);
std::vector<std::string> linkNames(hid_t group);

std::vector<hsize_t> toDims(const std::vector<std::uint64_t>& shape);

}  // namespace peristep::hdf5
