#include "names.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "granpipe/errors.hpp"

namespace granpipe {

namespace {

bool is_letter(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; }
bool is_word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool is_run_name_char(char c) { return is_word_char(c) || c == '-' || c == '.'; }

bool is_run_name(const std::string& s) {
  return !s.empty() && s.size() <= kMaxNameLength && s[0] != '.' &&
         std::all_of(s.begin(), s.end(), is_run_name_char);
}

bool is_analyzer_name(const std::string& s) {
  return !s.empty() && s.size() <= kMaxNameLength && is_letter(s[0]) &&
         std::all_of(s.begin(), s.end(), is_word_char) && s != "source" && s != "sweep" &&
         s.rfind("point_", 0) != 0;
}

const std::string kRunNameRule = "a name of at most " + std::to_string(kMaxNameLength) +
                                 " letters, digits, _, - and . (not first)";

}  // namespace

std::string read_pipeline_name(const nlohmann::json& root, const JsonLocation& top,
                               const std::string& origin) {
  const JsonLocation at = top.child("name");
  if (!root.contains("name")) {
    const std::string stem = std::filesystem::path(origin).stem().string();
    if (!is_run_name(stem)) {
      throw InputError(at.str() + ": expected " + kRunNameRule + ", got none, and the file name " +
                       json_brief(stem) + " is not one");
    }
    return stem;
  }
  const nlohmann::json& name = root["name"];
  if (!name.is_string() || !is_run_name(name.get<std::string>())) {
    throw InputError(at.str() + ": expected " + kRunNameRule + ", got " + json_brief(name));
  }
  return name.get<std::string>();
}

void check_analyzer_name(const nlohmann::json& name, const JsonLocation& at) {
  if (!name.is_string() || !is_analyzer_name(name.get<std::string>())) {
    throw InputError(
        at.str() + ": expected a name of at most " + std::to_string(kMaxNameLength) +
        " letters, digits and _, starting with a letter (not source, sweep or point_*), got " +
        json_brief(name));
  }
}

}  // namespace granpipe
