#include "strict_json.hpp"

#include <unordered_set>
#include <vector>

#include "granpipe/errors.hpp"
#include "granpipe/text_words.hpp"

namespace granpipe {
using json = nlohmann::json;

namespace {

// Follows the parser's events to know the JSON path of what is being read, and refuses
// what the DOM must not hold.
class StrictReader {
 public:
  StrictReader(std::string origin, std::size_t outer_depth)
      : origin_(std::move(origin)), outer_depth_(outer_depth) {}

  bool operator()(int /*depth*/, json::parse_event_t event, json& parsed) {
    using E = json::parse_event_t;
    switch (event) {
      case E::object_start:
      case E::array_start:
        open(event == E::array_start);
        break;
      case E::key:
        refuse_nul(parsed, true);
        read_key(parsed.get<std::string>());
        break;
      case E::value:
        refuse_nul(parsed, false);
        element_done();
        break;
      case E::object_end:
      case E::array_end:
        levels_.pop_back();
        element_done();
        break;
    }
    return true;
  }

  // The JSON library's "number overflow parsing '1e400'", said with the number's path.
  InputError number_overflow(const json::out_of_range& e) const {
    const std::string what = e.what();
    const auto open = what.find('\''), close = what.rfind('\'');
    const std::string token = open < close ? what.substr(open + 1, close - open - 1) : "?";
    return InputError(where(element_path()) +
                      ": expected a number of magnitude below 1.8e308, got " + token);
  }

 private:
  struct Level {
    bool is_array = false;
    std::string path;
    std::size_t index = 0;                 // of the element being read, in an array
    std::string key;                       // of the element being read, in an object
    std::unordered_set<std::string> keys;  // read so far, in an object
  };

  std::string where(const std::string& path) const {
    return path.empty() ? origin_ : origin_ + ": " + path;
  }

  // The path of the element being read now.
  std::string element_path() const {
    if (levels_.empty()) return "";
    const Level& top = levels_.back();
    if (top.is_array) return top.path + "[" + std::to_string(top.index) + "]";
    return top.path.empty() ? top.key : top.path + "." + top.key;
  }

  void open(bool is_array) {
    const std::string path = element_path();
    if (outer_depth_ + levels_.size() >= kMaxJsonDepth) {
      throw InputError(where(path) + ": expected JSON nested at most " +
                       std::to_string(kMaxJsonDepth) + " levels deep, got deeper");
    }
    levels_.push_back({is_array, path, 0, {}, {}});
  }

  // A string holding \u0000 ends at it wherever it becomes a C string (a file name read
  // as its part before the NUL, the pipeline recording the whole).
  void refuse_nul(const json& parsed, bool is_key) const {
    if (!parsed.is_string() || parsed.get_ref<const std::string&>().find('\0') == std::string::npos)
      return;
    const std::string path = is_key ? levels_.back().path : element_path();
    throw InputError(where(path) + ": expected " + (is_key ? "a key" : "a string") +
                     " without a NUL character, got one holding \\u0000");
  }

  // The JSON library would keep the last of two equal keys; the user meant one of them.
  void read_key(const std::string& key) {
    Level& top = levels_.back();
    top.key = key;
    if (!top.keys.insert(key).second) {
      throw InputError(where(element_path()) + ": expected each key once in an object, got \"" +
                       key + "\" again");
    }
  }

  void element_done() {
    if (!levels_.empty() && levels_.back().is_array) ++levels_.back().index;
  }

  std::string origin_;
  std::size_t outer_depth_;
  std::vector<Level> levels_;
};

// "origin:line:column" of the byte at `offset` (0-based) of `text`.
std::string place_of(const std::string& text, std::size_t offset, const std::string& origin) {
  std::size_t line = 1, col = 1;
  for (std::size_t k = 0; k < offset && k < text.size(); ++k) {
    if (text[k] == '\n') {
      ++line;
      col = 1;
    } else {
      ++col;
    }
  }
  return origin + ":" + std::to_string(line) + ":" + std::to_string(col);
}

json parse_or_throw(const std::string& text, const std::string& origin, std::size_t outer_depth) {
  // The parser takes a NUL byte for the end of the input: what follows one was ignored.
  if (const std::size_t nul = text.find('\0'); nul != std::string::npos) {
    throw InputError(place_of(text, nul, origin) +
                     ": malformed JSON: expected text, got a NUL byte (is it a binary file?)");
  }
  StrictReader reader(origin, outer_depth);
  try {
    return json::parse(
        text, [&reader](int d, json::parse_event_t e, json& v) { return reader(d, e, v); }, true,
        /*ignore_comments=*/true);
  } catch (const json::out_of_range& e) {
    if (e.id == 406) throw reader.number_overflow(e);
    throw;
  }
}

}  // namespace

std::size_t first_invalid_utf8(const std::string& text) {
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t n = utf8_length(std::string_view(text).substr(i));
    if (n == 0) return i;
    i += n;
  }
  return std::string::npos;
}

json parse_strict_json(const std::string& text, const std::string& origin,
                       std::size_t outer_depth) {
  try {
    return parse_or_throw(text, origin, outer_depth);
  } catch (const json::parse_error& e) {
    std::string reason = e.what();
    const auto colon = reason.find(": ", reason.find("parse error"));
    if (colon != std::string::npos) reason = reason.substr(colon + 2);
    // e.byte counts from 1.
    throw InputError(place_of(text, e.byte > 0 ? e.byte - 1 : 0, origin) +
                     ": malformed JSON: " + reason);
  }
}

std::optional<json> parse_strict_json_if_json(const std::string& text, const std::string& origin,
                                              std::size_t outer_depth) {
  try {
    return parse_or_throw(text, origin, outer_depth);
  } catch (const json::parse_error&) {
    return std::nullopt;
  }
}

}  // namespace granpipe
