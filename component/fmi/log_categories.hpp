#pragma once
// The log categories of <LogCategories> in modelDescription.xml, shared by the logger and the
// model-description generator so that the two cannot disagree.
#include <array>
#include <cstddef>
#include <string_view>

namespace peristep::fmi {

enum class LogCategory : std::size_t { Events, StatusWarning, StatusError, Progress };

struct LogCategoryInfo {
  LogCategory id;
  std::string_view name;
  std::string_view description;
  bool onWhenLoggingOn;  // enabled by loggingOn = true at instantiation (the "vendor defined set")
};

inline constexpr std::array<LogCategoryInfo, 4> kLogCategories{{
    {LogCategory::Events, "logEvents",
     "Mode changes, scene set-up and every communication step (debug detail)", false},
    {LogCategory::StatusWarning, "logStatusWarning",
     "Messages of calls returning fmi3Warning (PeriStep returns none in normal operation)", true},
    {LogCategory::StatusError, "logStatusError",
     "Why a call returned fmi3Error: illegal call sequence, bad argument, invalid value, solver failure "
     "(always reported, whatever loggingOn and fmi3SetDebugLogging say)",
     true},
    {LogCategory::Progress, "logProgress",
     "How far a long initialization or step has come, as 'progress: <phase> <done>/<total>' (phases setUp, "
     "pcaRealizations, internalSteps)",
     false},
}};

}  // namespace peristep::fmi
