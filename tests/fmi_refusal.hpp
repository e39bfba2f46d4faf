#pragma once
// A call through the C ABI that must be refused: fmi3Error and exactly one logStatusError message that
// names the function and contains the fragment.
#include <catch2/catch.hpp>
#include <functional>
#include <string>

#include "fmi_abi_support.hpp"

inline void requireRefused(Session& s, const std::string& function, const std::string& fragment,
                           const std::function<fmi3Status()>& call) {
  using Catch::Matchers::Contains;
  using Catch::Matchers::StartsWith;
  s.log.clear();
  CHECK(call() == fmi3Error);
  REQUIRE(s.log.records.size() == 1);
  const LogRecord& r = s.log.records.front();
  CHECK(r.status == fmi3Error);
  CHECK(r.category == "logStatusError");
  CHECK_THAT(r.message, StartsWith(function + ": "));
  CHECK_THAT(r.message, Contains(fragment));
}
