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

// How a lead byte of UTF-8 goes on: its continuation bytes, and the range of the first
// (narrower than 0x80..0xbf where that would allow overlong forms, surrogates or code
// points beyond U+10FFFF). No continuation bytes: not a lead byte.
struct Utf8Lead {
  int continuation;
  unsigned char first_min, first_max;
};

Utf8Lead utf8_lead(unsigned char c) {
  if (c >= 0xc2 && c <= 0xdf) return {1, 0x80, 0xbf};
  if (c == 0xe0) return {2, 0xa0, 0xbf};
  if (c == 0xed) return {2, 0x80, 0x9f};
  if (c >= 0xe1 && c <= 0xef) return {2, 0x80, 0xbf};
  if (c == 0xf0) return {3, 0x90, 0xbf};
  if (c >= 0xf1 && c <= 0xf3) return {3, 0x80, 0xbf};
  if (c == 0xf4) return {3, 0x80, 0x8f};
  return {0, 0, 0};
}

// A character well formed but not to be shown as it is: a bidirectional control (U+061C,
// U+200E, U+200F, U+202A..U+202E, U+2066..U+2069), by which a terminal reorders the rest of
// the line, or one of no width (U+200B..U+200D, U+2060, and U+FEFF, the byte-order mark an
// editor puts before a file's first line: "expected ITEM: TIMESTEP, got ITEM: TIMESTEP").
bool hidden_or_reordering(std::string_view c) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(c[k]); };
  if (c.size() == 2) return byte(0) == 0xD8 && byte(1) == 0x9C;
  if (c.size() != 3) return false;
  if (byte(0) == 0xEF) return byte(1) == 0xBB && byte(2) == 0xBF;
  if (byte(0) != 0xE2) return false;
  const unsigned char b = byte(1), last = byte(2);
  return (b == 0x80 && ((last >= 0x8B && last <= 0x8F) || (last >= 0xAA && last <= 0xAE))) ||
         (b == 0x81 && (last == 0xA0 || (last >= 0xA6 && last <= 0xA9)));
}

}  // namespace

std::size_t utf8_length(std::string_view s) {
  if (s.empty()) return 0;
  const auto c = static_cast<unsigned char>(s[0]);
  if (c < 0x80) return 1;
  const Utf8Lead lead = utf8_lead(c);
  const auto n = static_cast<std::size_t>(lead.continuation) + 1;
  if (lead.continuation == 0 || n > s.size()) return 0;
  for (std::size_t k = 1; k < n; ++k) {
    const auto b = static_cast<unsigned char>(s[k]);
    const unsigned char min = k == 1 ? lead.first_min : 0x80, max = k == 1 ? lead.first_max : 0xbf;
    if (b < min || b > max) return 0;
  }
  return n;
}

std::string quoted(std::string_view line) {
  const std::string_view kept = line.substr(0, kQuotedLength);
  // A binary file's bytes would garble the terminal; UTF-8 text is shown as it is (a unit
  // "µm" read "??m").
  std::string shown = "\"";
  for (std::size_t k = 0; k < kept.size();) {
    const auto c = static_cast<unsigned char>(kept[k]);
    // A C1 control (U+0080..U+009F: CSI is one) is well-formed but terminals obey it.
    const bool c1 =
        c == 0xC2 && k + 1 < kept.size() && static_cast<unsigned char>(kept[k + 1]) < 0xA0;
    const std::size_t n = c1 ? 0 : utf8_length(kept.substr(k));
    if ((n > 1 && !hidden_or_reordering(kept.substr(k, n))) || (n == 1 && std::isprint(c))) {
      shown += kept.substr(k, n);
    } else {
      shown += '?';
    }
    k += n == 0 ? 1 : n;
  }
  shown += line.size() > kQuotedLength ? "...\"" : "\"";
  return shown;
}

}  // namespace granpipe
