#include "contact_columns.hpp"

#include <algorithm>

#include "granpipe/errors.hpp"

namespace granpipe::lammps_dump {

namespace {

struct LiggghtsKeyword {
  const char* name;
  int values;
};

// In the order LIGGGHTS writes them (compute_pair_gran_local.cpp, nvalues), history and
// the later contactPoint and ms_id left out: history's count depends on the contact model.
constexpr LiggghtsKeyword kLiggghts[] = {{"pos", 6},          {"vel", 6},
                                         {"id", 3},           {"force", 3},
                                         {"force_normal", 3}, {"force_tangential", 3},
                                         {"torque", 3},       {"contactArea", 1},
                                         {"delta", 1},        {"heatFlux", 1}};

std::string joined(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : " ") + n;
  return s;
}

void check_repeats(const std::vector<std::string>& keywords, const std::string& param) {
  for (std::size_t k = 0; k < keywords.size(); ++k) {
    if (std::find(keywords.begin(), keywords.begin() + static_cast<long>(k), keywords[k]) !=
        keywords.begin() + static_cast<long>(k)) {
      throw InputError(param + ": expected each keyword once, got \"" + keywords[k] + "\" again");
    }
  }
}

std::array<int, 3> three(int first) { return {first, first + 1, first + 2}; }

ContactColumns liggghts_columns(const std::vector<std::string>& keywords, bool wall,
                                const std::string& param) {
  ContactColumns c;
  int at = 0;
  for (const LiggghtsKeyword& k : kLiggghts) {
    if (std::find(keywords.begin(), keywords.end(), k.name) == keywords.end()) continue;
    const std::string name = k.name;
    if (name == "pos" && wall) c.point = three(at);
    if (name == "id") {
      c.id1 = wall ? at + 2 : at;  // a wall's mesh and triangle come first
      c.id2 = wall ? -1 : at + 1;
    }
    if (name == "force") c.force = three(at);
    if (name == "force_normal") c.normal = three(at);
    if (name == "force_tangential") c.tangential = three(at);
    if (name == "delta") c.overlap = at;
    at += k.values;
  }
  c.count = static_cast<std::size_t>(at);
  for (const auto& w : keywords) {
    if (std::none_of(std::begin(kLiggghts), std::end(kLiggghts),
                     [&](const LiggghtsKeyword& k) { return w == k.name; })) {
      throw InputError(param +
                       ": expected keywords of compute pair/gran/local or "
                       "wall/gran/local (pos vel id force force_normal force_tangential "
                       "torque contactArea delta heatFlux), got \"" +
                       w + "\"");
    }
  }
  return c;
}

// LAMMPS keywords the source lets be: p4 ... p99 are pair-style extras past the tangential
// force.
bool unused_lammps_keyword(const std::string& w) {
  if (w == "eng" || w == "force" || w == "ptype1" || w == "ptype2") return true;
  const bool extra = w.size() >= 2 && w.size() <= 3 && w[0] == 'p' &&
                     w.find_first_not_of("0123456789", 1) == std::string::npos;
  return extra && std::stoi(w.substr(1)) >= 4;
}

ContactColumns lammps_columns(const std::vector<std::string>& keywords, const std::string& param) {
  ContactColumns c;
  c.count = keywords.size();
  const std::vector<std::pair<std::string, int*>> read{
      {"patom1", &c.id1},       {"patom2", &c.id2},       {"fx", &c.normal[0]},
      {"fy", &c.normal[1]},     {"fz", &c.normal[2]},     {"p1", &c.tangential[0]},
      {"p2", &c.tangential[1]}, {"p3", &c.tangential[2]}, {"dist", &c.distance}};
  for (std::size_t k = 0; k < keywords.size(); ++k) {
    const auto found = std::find_if(read.begin(), read.end(),
                                    [&](const auto& r) { return r.first == keywords[k]; });
    if (found != read.end()) {
      *found->second = static_cast<int>(k);
    } else if (!unused_lammps_keyword(keywords[k])) {
      throw InputError(param +
                       ": expected keywords of compute property/local or pair/local "
                       "(patom1 patom2 fx fy fz p1 p2 p3 dist, or eng force ptype1 ptype2 "
                       "p4 ... kept out), got \"" +
                       keywords[k] + "\"");
    }
  }
  const bool some = c.tangential[0] >= 0 || c.tangential[1] >= 0 || c.tangential[2] >= 0;
  if (some && (c.tangential[0] < 0 || c.tangential[1] < 0 || c.tangential[2] < 0)) {
    throw InputError(param + ": expected p1 p2 p3 (the tangential force) together, got \"" +
                     joined(keywords) + "\"");
  }
  return c;
}

void check_needed(const ContactColumns& c, ContactFormat format, bool wall,
                  const std::vector<std::string>& keywords, const std::string& param) {
  const bool liggghts = format == ContactFormat::Liggghts;
  const bool ids = c.id1 >= 0 && (wall || c.id2 >= 0);
  const bool normal = c.normal[0] >= 0 && c.normal[1] >= 0 && c.normal[2] >= 0;
  if (!ids || !normal) {
    throw InputError(param + ": expected " +
                     (liggghts ? "the keywords id and force_normal" : "patom1 patom2 fx fy fz") +
                     ", got \"" + joined(keywords) + "\"");
  }
}

}  // namespace

ContactColumns contact_columns(ContactFormat format, const std::vector<std::string>& keywords,
                               bool wall, const std::string& param) {
  check_repeats(keywords, param);
  ContactColumns c = format == ContactFormat::Liggghts ? liggghts_columns(keywords, wall, param)
                                                       : lammps_columns(keywords, param);
  check_needed(c, format, wall, keywords, param);
  return c;
}

}  // namespace granpipe::lammps_dump
