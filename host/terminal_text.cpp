#include "terminal_text.hpp"

namespace peristep::host {

namespace {

bool continuationByte(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

// Bytes of the first `characters` characters of `text` (never splits one).
std::size_t prefixBytes(std::string_view text, std::size_t characters) {
  std::size_t bytes = 0, seen = 0;
  while (bytes < text.size()) {
    if (!continuationByte(text[bytes]) && seen++ == characters) break;
    ++bytes;
  }
  return bytes;
}

}  // namespace

std::size_t displayWidth(std::string_view text) {
  std::size_t n = 0;
  for (char c : text) n += !continuationByte(c);
  return n;
}

std::string fitted(std::string_view text, std::size_t width) {
  if (displayWidth(text) <= width) return std::string(text);
  if (width <= 3) return std::string(width, '.');
  std::string out(text.substr(0, prefixBytes(text, width - 3)));
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out + "...";
}

std::vector<std::string> wrapped(std::string_view text, std::size_t width) {
  std::vector<std::string> lines;
  std::string line;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find(' ', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view word = text.substr(start, end - start);
    start = end + 1;
    if (word.empty()) continue;
    while (displayWidth(word) > width) {  // no space to break at: cut the word itself
      if (!line.empty()) lines.push_back(std::move(line)), line.clear();
      const std::size_t cut = prefixBytes(word, width);
      lines.emplace_back(word.substr(0, cut));
      word.remove_prefix(cut);
    }
    if (word.empty()) continue;
    if (!line.empty() && displayWidth(line) + 1 + displayWidth(word) > width) lines.push_back(std::move(line)), line.clear();
    line += (line.empty() ? "" : " ") + std::string(word);
  }
  if (!line.empty()) lines.push_back(std::move(line));
  return lines;
}

}  // namespace peristep::host
