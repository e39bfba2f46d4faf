#include "fmi/logging.hpp"

#include <cstring>
#include <string>

#include "core/errors.hpp"

namespace peristep::fmi {

Logger::Logger(fmi3LogMessageCallback callback, fmi3InstanceEnvironment environment, bool loggingOn)
    : callback_(callback), environment_(environment), loggingOn_(loggingOn) {
  reset();
}

void Logger::reset() {
  for (const auto& c : kLogCategories) enabled_[static_cast<std::size_t>(c.id)] = loggingOn_ && c.onWhenLoggingOn;
}

// A refusal always reaches the importer: with loggingOn = false an importer would otherwise see only the
// status code (the Reference FMUs report errors the same way).
void Logger::error(std::string_view message) const noexcept {
  log(LogCategory::StatusError, fmi3Error, message, true);
}

void Logger::event(std::string_view message) const noexcept { log(LogCategory::Events, fmi3OK, message); }

void Logger::progress(std::string_view phase, std::uint64_t done, std::uint64_t total) const noexcept {
  if (!progressOn()) return;
  try {
    log(LogCategory::Progress, fmi3OK,
        "progress: " + std::string(phase) + " " + std::to_string(done) + "/" + std::to_string(total));
  } catch (...) {
    // no memory for the message: progress is not worth an error
  }
}

void Logger::log(LogCategory c, fmi3Status status, std::string_view message, bool always) const noexcept {
  if (!callback_ || !(always || enabled(c))) return;
  try {
    // The callback needs a NUL-terminated copy; it must copy it again if it keeps it.
    const std::string text(message);
    callback_(environment_, status, kLogCategories[static_cast<std::size_t>(c)].name.data(), text.c_str());
  } catch (...) {
    // Out of memory for the copy: the message is lost, the caller's status still reports the error.
  }
}

void Logger::setDebugLogging(bool on, std::span<const fmi3String> categories) {
  if (categories.empty()) {
    enabled_.fill(on);
    return;
  }
  auto next = enabled_;
  for (fmi3String name : categories) {
    require(name != nullptr, "categories[] contains a NULL pointer");
    bool known = false;
    for (const auto& c : kLogCategories)
      if (c.name == name) {
        next[static_cast<std::size_t>(c.id)] = on;
        known = true;
      }
    std::string list;
    for (const auto& c : kLogCategories) list += (list.empty() ? "" : ", ") + std::string(c.name);
    require(known, "unknown log category '" + std::string(name) + "' (known: " + list + ")");
  }
  enabled_ = next;
}

}  // namespace peristep::fmi
