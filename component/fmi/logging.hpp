#pragma once
// The importer's logMessage callback behind the log categories of modelDescription.xml. Errors always
// reach it; loggingOn at instantiation and fmi3SetDebugLogging switch the other categories.
#include <array>
#include <cstdint>
#include <span>
#include <string_view>

#include "fmi/log_categories.hpp"
#include "fmi3FunctionTypes.h"

namespace peristep::fmi {

class Logger {
 public:
  Logger(fmi3LogMessageCallback callback, fmi3InstanceEnvironment environment, bool loggingOn);

  // Category logStatusError, status fmi3Error, whatever loggingOn says. Never throws.
  void error(std::string_view message) const noexcept;
  // Category logEvents, status fmi3OK.
  void event(std::string_view message) const noexcept;
  bool eventsOn() const { return enabled(LogCategory::Events); }
  // Category logProgress, status fmi3OK: "progress: <phase> <done>/<total>". Never throws.
  void progress(std::string_view phase, std::uint64_t done, std::uint64_t total) const noexcept;
  bool progressOn() const { return enabled(LogCategory::Progress); }

  // fmi3SetDebugLogging: no categories means all of them. Throws InvalidInput for an unknown name
  // (and then changes nothing).
  void setDebugLogging(bool on, std::span<const fmi3String> categories);
  // Back to the categories chosen at instantiation (fmi3Reset).
  void reset();

 private:
  bool enabled(LogCategory c) const { return enabled_[static_cast<std::size_t>(c)]; }
  void log(LogCategory c, fmi3Status status, std::string_view message, bool always = false) const noexcept;

  fmi3LogMessageCallback callback_;
  fmi3InstanceEnvironment environment_;
  bool loggingOn_;
  std::array<bool, kLogCategories.size()> enabled_{};
};

}  // namespace peristep::fmi
