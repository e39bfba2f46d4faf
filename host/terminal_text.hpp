#pragma once
// Text for an 80-100 column terminal: widths in characters (UTF-8 code points, so "µm" is two wide),
// one-line summaries cut to a width, paragraphs wrapped at word boundaries.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace peristep::host {

// The terminal width `peristep info` keeps to.
inline constexpr std::size_t kTerminalWidth = 100;

std::size_t displayWidth(std::string_view text);

// `text` if it fits in `width` characters, else its start and "..." in exactly `width`.
std::string fitted(std::string_view text, std::size_t width);

// Lines of at most `width` characters, broken at spaces (a longer word is cut).
std::vector<std::string> wrapped(std::string_view text, std::size_t width);

}  // namespace peristep::host
