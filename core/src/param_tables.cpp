#include "param_tables.hpp"

#include <algorithm>
#include <cctype>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "did_you_mean.hpp"
#include "granpipe/errors.hpp"

namespace granpipe {
using json = nlohmann::json;

namespace {

constexpr std::size_t kMaxSpeciesName = 100;

// Letters, digits and _, a letter first: a species name fits a pair key "a-b" and a
// --set path unchanged.
bool is_species_name(const std::string& s) {
  const auto is_name_char = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  };
  return !s.empty() && s.size() <= kMaxSpeciesName &&
         std::isalpha(static_cast<unsigned char>(s[0])) &&
         std::all_of(s.begin(), s.end(), is_name_char);
}

void check_species_name(const std::string& name, const std::vector<std::string>& earlier,
                        const JsonLocation& at) {
  if (!is_species_name(name)) {
    throw InputError(at.str() +
                     ": expected a species name (a letter, then letters, digits and _; at most " +
                     std::to_string(kMaxSpeciesName) + "), got " + json_brief(name));
  }
  if (std::find(earlier.begin(), earlier.end(), name) != earlier.end()) {
    throw InputError(at.str() + ": expected a name no other species has, got " + json_brief(name) +
                     " again");
  }
}

// The species indices (i <= j) of a pair key "a-b".
std::pair<std::size_t, std::size_t> pair_of(const std::string& key, const SpeciesTable& species,
                                            const JsonLocation& table) {
  const auto dash = key.find('-');
  const std::string a = key.substr(0, dash),
                    b = dash == std::string::npos ? "" : key.substr(dash + 1);
  std::vector<std::string> names;
  for (std::size_t i = 0; i < species.size(); ++i) names.push_back(species.name(i));
  const JsonLocation at = table.child(key);
  if (!is_species_name(a) || !is_species_name(b)) {
    std::string list;
    for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
    // A key from where the table came from (the file, or a --set of the whole table) is
    // shown quoted only: it may hold any character. One a --set of its own made (setting a
    // value inside it; a --set path holds names only) is named with that --set.
    const bool own_set = at.origin() != table.origin();
    const std::string where = own_set ? at.key_str() : table.str();
    throw InputError(where + ": expected keys \"a-b\" naming two species (of " + list +
                     ") or \"*\", got " + json_brief(key));
  }
  std::size_t ends[2];
  for (int k = 0; k < 2; ++k) {
    const std::string& name = k == 0 ? a : b;
    const auto i = species.find(name);
    if (!i) {
      throw InputError(at.key_str() + ": unknown species \"" + name + "\"" +
                       did_you_mean(name, names) + known_list(names));
    }
    ends[k] = *i;
  }
  return std::minmax(ends[0], ends[1]);
}

}  // namespace

ParamValue read_species_table(const json& list, const ParamSpec& spec, const JsonLocation& at,
                              const std::filesystem::path& base_dir) {
  if (!list.is_array() || list.empty()) {
    throw InputError(at.str() + ": expected " + describe_expected(spec) + ", got " +
                     json_brief(list));
  }
  if (list.size() > kMaxSpecies) {
    throw InputError(at.str() + ": expected at most " + std::to_string(kMaxSpecies) +
                     " species, got " + std::to_string(list.size()));
  }
  std::vector<Params> rows;
  std::vector<std::string> names;
  for (std::size_t k = 0; k < list.size(); ++k) {
    Params row = read_params(list[k], *spec.fields, at.index(k), base_dir);
    check_species_name(row.string("name"), names, at.index(k).child("name"));
    names.push_back(row.string("name"));
    rows.push_back(std::move(row));
  }
  return std::make_shared<const SpeciesTable>(std::move(rows));
}

ParamValue read_pair_table(const json& table, const ParamSpec& spec, const SpeciesTable& species,
                           const JsonLocation& at, const std::filesystem::path& base_dir) {
  if (!table.is_object()) {
    throw InputError(at.str() + ": expected " + describe_expected(spec) + ", got " +
                     json_brief(table));
  }
  const std::size_t n = species.size();
  std::vector<std::string> given(n * n);  // the key that gave pair (i, j), at i * n + j
  const json* all = nullptr;
  for (const auto& [key, entry] : table.items()) {
    const JsonLocation entry_at = at.child(key);
    if (key == "*") {
      all = &entry;
    } else {
      const auto [i, j] = pair_of(key, species, at);
      if (!given[i * n + j].empty()) {
        throw InputError(entry_at.str() +
                         ": expected each pair once (a-b is b-a), got it also as \"" +
                         given[i * n + j] + "\"");
      }
      given[i * n + j] = key;
    }
    read_params(entry, *spec.fields, entry_at, base_dir, Missing::Skip);
  }
  std::vector<Params> pairs;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i; j < n; ++j) {
      const std::string& key = given[i * n + j];
      if (key.empty() && !all) {
        throw InputError(at.str() +
                         ": expected an entry for every pair of species, got none for \"" +
                         species.name(i) + "-" + species.name(j) +
                         "\" (give it, or \"*\" for the pairs not listed)");
      }
      json merged = all ? *all : json::object();
      if (!key.empty()) merged.update(table.at(key));
      pairs.push_back(
          read_params(merged, *spec.fields, at.child(key.empty() ? "*" : key), base_dir));
    }
  }
  std::vector<std::string> names;
  for (std::size_t i = 0; i < n; ++i) names.push_back(species.name(i));
  return std::make_shared<const PairTable>(std::move(names), std::move(pairs));
}

void check_table_default(const ParamSpec& spec, const Schema& schema) {
  if (!spec.default_json) return;
  const JsonLocation at{"default", spec.name, nullptr};
  try {
    const json value = json::parse(*spec.default_json);
    if (spec.type == ParamType::Species) {
      read_species_table(value, spec, at, {});
      return;
    }
    const ParamSpec& table = *schema.find(spec.species);
    if (!table.default_json) return;  // the species are the pipeline's: checked when it is read
    const auto species = std::get<std::shared_ptr<const SpeciesTable>>(
        read_species_table(json::parse(*table.default_json), table, at, {}));
    read_pair_table(value, spec, *species, at, {});
  } catch (const std::exception& e) {
    throw InternalError("schema: the default of '" + spec.name + "' is refused: " + e.what());
  }
}

}  // namespace granpipe
