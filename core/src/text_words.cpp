#include "granpipe/text_words.hpp"

#include <cctype>
#include <charconv>

namespace granpipe {

namespace {

constexpr std::string_view kBlanks = " \t";
// Enough of a line to recognise it; a dump's lines can be thousands of characters long.
constexpr std::size_t kQuotedLength = 60;

// A leading '+' as C's strtod accepts it (std::from_chars does not), a sign only once.
std::string_view without_plus(std::string_view word) {
  if (word.starts_with('+') && !word.starts_with("+-")) word.remove_prefix(1);
  return word;
}

}  // namespace

std::vector<std::string_view> words(std::string_view line) {
  std::vector<std::string_view> out;
  split_words(line, out);
  return out;
}

void split_words(std::string_view line, std::vector<std::string_view>& out) {
  out.clear();
  std::size_t start = line.find_first_not_of(kBlanks);
  while (start != std::string_view::npos) {
    const std::size_t end = line.find_first_of(kBlanks, start);
    out.push_back(line.substr(start, end - start));
    start = line.find_first_not_of(kBlanks, end);
  }
}

std::string_view trimmed(std::string_view line) {
  const std::size_t end = line.find_last_not_of(kBlanks);
  return end == std::string_view::npos ? std::string_view{} : line.substr(0, end + 1);
}

std::optional<std::int64_t> whole_number(std::string_view word) {
  word = without_plus(word);
  std::int64_t value = 0;
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (error != std::errc{} || end != word.data() + word.size()) return {};
  return value;
}

std::optional<double> real_number(std::string_view word) {
  word = without_plus(word);
  double value = 0.0;
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (error != std::errc{} || end != word.data() + word.size()) return {};
  return value;
}

std::string quoted(std::string_view line) {
  std::string shown(line.substr(0, kQuotedLength));
  // A binary file's bytes would garble the terminal.
  for (char& c : shown) {
    if (!std::isprint(static_cast<unsigned char>(c))) c = '?';
  }
  return "\"" + shown + (line.size() > kQuotedLength ? "...\"" : "\"");
}

}  // namespace granpipe
