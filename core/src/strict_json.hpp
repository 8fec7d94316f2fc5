#pragma once
// Reading JSON text strictly, before a DOM is built that later code could trip on:
// nesting at most kMaxJsonDepth levels deep, no key twice in one object, numbers that fit
// a double. Every refusal is an InputError naming the JSON path.
#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace granpipe {

// Deeper than any pipeline needs, shallow enough for recursive code on the result.
inline constexpr std::size_t kMaxJsonDepth = 64;

// `origin` starts every message ("p.json", "--set a=b"); malformed text is refused with
// its line and column. Comments are allowed. `outer_depth` counts levels that enclose
// the text where its value will be placed.
nlohmann::json parse_strict_json(const std::string& text, const std::string& origin,
                                 std::size_t outer_depth = 0);

// The offset of the first byte of `text` that is not well-formed UTF-8, or npos. JSON
// strings are UTF-8: a string holding anything else throws when it is written out.
std::size_t first_invalid_utf8(const std::string& text);

// Like parse_strict_json, but text that is not JSON at all gives nothing.
std::optional<nlohmann::json> parse_strict_json_if_json(const std::string& text,
                                                        const std::string& origin,
                                                        std::size_t outer_depth = 0);

}  // namespace granpipe
