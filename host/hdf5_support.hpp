#pragma once
// The host's pieces over the shared HDF5 layer (hdf5/hdf5_io.hpp): the result layout's attributes and
// descriptions, and the layer's errors turned into the host's RunError ("writing results failed").
#include <utility>

#include "hdf5_io.hpp"
#include "host_errors.hpp"
#include "result_layout.hpp"

namespace peristep::host {

// Runs `work`; an hdf5::Error it throws comes out as RunError with the same message.
template <class Work>
decltype(auto) asRunError(Work&& work) {
  try {
    return std::forward<Work>(work)();
  } catch (const hdf5::Error& e) {
    throw RunError(e.what());
  }
}

// A one-element vector is stored as a scalar attribute.
void writeAttribute(hid_t object, const Attribute& a);
// Unit and description attributes of a dataset.
void describe(hid_t object, const ArrayInfo& info);

}  // namespace peristep::host
