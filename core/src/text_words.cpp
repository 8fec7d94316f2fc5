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

namespace {

// The length of the printable UTF-8 character at the start of `s` (2 to 4 bytes, as RFC 3629
// allows them: no overlong form, surrogate or code point past U+10FFFF), or 0 where it is
// none (a byte of a binary file, or a C1 control such as U+009B, which terminals obey).
std::size_t utf8_length(std::string_view s) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char lead = byte(0);
  const std::size_t n = lead >= 0xF0 && lead <= 0xF4 ? 4 : lead >= 0xE0 ? 3 : lead >= 0xC2 ? 2 : 0;
  if (lead >= 0xF5 || n == 0 || n > s.size()) return 0;
  for (std::size_t k = 1; k < n; ++k)
    if ((byte(k) & 0xC0) != 0x80) return 0;
  const unsigned char second = byte(1);
  const bool valid = !(lead == 0xC2 && second < 0xA0) && !(lead == 0xE0 && second < 0xA0) &&
                     !(lead == 0xED && second >= 0xA0) && !(lead == 0xF0 && second < 0x90) &&
                     !(lead == 0xF4 && second >= 0x90);
  return valid ? n : 0;
}

}  // namespace

std::string quoted(std::string_view line) {
  const std::string_view kept = line.substr(0, kQuotedLength);
  // A binary file's bytes would garble the terminal; UTF-8 text is shown as it is (a unit
  // "µm" read "??m").
  std::string shown = "\"";
  for (std::size_t k = 0; k < kept.size();) {
    const auto c = static_cast<unsigned char>(kept[k]);
    const std::size_t n = c < 0x80 ? 1 : utf8_length(kept.substr(k));
    if (n == 1 && std::isprint(c)) shown += kept[k];
    if (n > 1) shown += kept.substr(k, n);
    if (n <= 1 && !std::isprint(c)) shown += '?';
    k += n == 0 ? 1 : n;
  }
  shown += line.size() > kQuotedLength ? "...\"" : "\"";
  return shown;
}

}  // namespace granpipe
