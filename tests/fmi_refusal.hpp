#pragma once
// Refusals through the C ABI: fmi3Error and exactly one logStatusError message that names the function and
// contains the fragment.
#include <catch2/catch.hpp>
#include <functional>
#include <string>

#include "fmi_abi_support.hpp"

// The single message of a failed call.
inline void requireOneError(const Session& s, const std::string& function, const std::string& fragment) {
  using Catch::Matchers::Contains;
  using Catch::Matchers::StartsWith;
  REQUIRE(s.log.records.size() == 1);
  const LogRecord& r = s.log.records.front();
  CHECK(r.status == fmi3Error);
  CHECK(r.category == "logStatusError");
  CHECK_THAT(r.message, StartsWith(function + ": "));
  CHECK_THAT(r.message, Contains(fragment));
}

// Runs a call that must be refused.
inline void requireRefused(Session& s, const std::string& function, const std::string& fragment,
                           const std::function<fmi3Status()>& call) {
  s.log.clear();
  CHECK(call() == fmi3Error);
  requireOneError(s, function, fragment);
}
