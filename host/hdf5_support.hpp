#pragma once
// Small pieces of the HDF5 C API shared by the run writer and the sample-study writer: an owning
// handle, status checks with one-line messages, attributes and plain (non-extendible) datasets.
#include <hdf5.h>

#include <cstdint>
#include <string>
#include <vector>

#include "result_layout.hpp"

namespace peristep::host {

// Owns one HDF5 identifier and closes it with the function that matches its kind.
class Handle {
 public:
  Handle(hid_t id, herr_t (*closer)(hid_t), const std::string& what);
  ~Handle() { closer_(id_); }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  operator hid_t() const { return id_; }

 private:
  hid_t id_;
  herr_t (*closer_)(hid_t);
};

// Throws RunError("HDF5: cannot <what>") for a negative status.
void check(herr_t status, const std::string& what);
void writeString(hid_t object, const std::string& name, const std::string& value);
// A one-element vector is stored as a scalar attribute.
void writeAttribute(hid_t object, const Attribute& a);
// Unit and description attributes of a dataset.
void describe(hid_t object, const ArrayInfo& info);
std::vector<hsize_t> toDims(const std::vector<std::uint64_t>& shape);
// A dataset of doubles with the given shape (empty shape: a scalar), written whole.
void writeDataset(hid_t parent, const std::string& name, const std::vector<std::uint64_t>& shape, const double* data);
// A group, created (intermediate groups too).
hid_t createGroup(hid_t parent, const std::string& path);

}  // namespace peristep::host
