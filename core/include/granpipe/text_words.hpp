#pragma once
// The pieces of a line of text as LAMMPS writes its dumps and data files: words, numbers,
// the line quoted in a message.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace granpipe {

// The words of a line, split at spaces and tabs (trailing ones included).
std::vector<std::string_view> words(std::string_view line);
// The same into `out`, whose memory is reused line after line.
void split_words(std::string_view line, std::vector<std::string_view>& out);
// The line without the spaces and tabs that end it.
std::string_view trimmed(std::string_view line);
// The whole word as a number, or nothing: "12", "-3"; "1.5" and "12abc" are not whole.
std::optional<std::int64_t> whole_number(std::string_view word);
// The whole word as a number, or nothing: "0.5", "-1e-3", "+2"; "nan" and "inf" are numbers
// here (callers decide whether they accept them).
std::optional<double> real_number(std::string_view word);
// The length of the character that starts `s` as UTF-8: 1 (ASCII), 2 to 4 where it is
// well-formed (RFC 3629: no overlong form, surrogate or code point past U+10FFFF), 0 where
// it is not (or `s` is empty).
std::size_t utf8_length(std::string_view s);
// The start of a line, in quotes, for a message: "\"1 1 0.5 0 0\"" (printable ASCII and
// UTF-8 characters as they are, other bytes as '?').
std::string quoted(std::string_view line);

}  // namespace granpipe
