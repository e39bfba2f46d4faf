#pragma once
// The notched plate of notched_plate.hpp through the C ABI: its notch as the specimen's one pre-crack.
#include <catch2/catch.hpp>

#include "fmi_abi_support.hpp"
#include "notched_plate.hpp"

inline void setNotch(Session& s) {
  using notched_plate::kNotch;
  REQUIRE(s.setFloat64(PERISTEP_VR_CRACK_X0, {kNotch[0]}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_CRACK_Y0, {kNotch[1]}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_CRACK_X1, {kNotch[2]}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_CRACK_Y1, {kNotch[3]}) == fmi3OK);
}
