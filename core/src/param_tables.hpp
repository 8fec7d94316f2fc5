#pragma once
// Reading the species and pair tables of a schema (Schema::species_table, pair_table).
#include <cstddef>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "granpipe/params.hpp"
#include "param_validation.hpp"

namespace granpipe {

// More species than a scene of different materials has; a pair table holds S(S+1)/2 objects.
inline constexpr std::size_t kMaxSpecies = 256;

// A list of species objects, each with a unique name, against `spec.fields`.
ParamValue read_species_table(const nlohmann::json& list, const ParamSpec& spec,
                              const JsonLocation& at, const std::filesystem::path& base_dir);

// An object keyed "a-b" (species a and b of `species`) and "*", with every pair given
// or "*"; each pair's values are "*"'s overridden by its own.
ParamValue read_pair_table(const nlohmann::json& table, const ParamSpec& spec,
                           const SpeciesTable& species, const JsonLocation& at,
                           const std::filesystem::path& base_dir);

// Refuses (InternalError) a table's default JSON that `schema`'s reader would refuse; a
// pair table's is read against its species table's default, if any.
void check_table_default(const ParamSpec& spec, const Schema& schema);

}  // namespace granpipe
