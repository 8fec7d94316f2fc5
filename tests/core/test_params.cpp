// Parameters beyond numbers and strings, read through a pipeline as a plugin gets them:
// choices read as enums, nested objects, species tables and species-pair tables. Every
// bad value gives one line naming the file and the JSON path of the offending entry.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "granpipe/pipeline.hpp"
#include "plugin_harness.hpp"

using namespace granpipe;

namespace {

enum class Law : std::uint8_t { Linear, Hertz };
ChoiceNames<Law> choice_names(Law) { return {{"linear", Law::Linear}, {"hertz", Law::Hertz}}; }

// The parameters the last MaterialSource was made with.
std::optional<Params> made_with;

class MaterialSource : public Source {
 public:
  explicit MaterialSource(const PluginContext& c) { made_with = c.params; }
  FrameContent content() const override { return {.dim = 3}; }
  bool next(Frame&) override { return false; }
};

Schema wall() {
  Schema s;
  s.real("k_n", std::nullopt, "normal stiffness").min(0.0, true);
  s.real("mu", 0.5, "friction coefficient").min(0.0);
  return s;
}

Registry material_registry() {
  Schema walls;
  walls.object("base", wall(), "the flat base");
  walls.object("cylinder", wall(), "the side wall");
  Schema species;
  species.real("diameter", std::nullopt, "diameter").min(0.0, true);
  species.real("density", std::nullopt, "mass density").min(0.0, true);
  Schema pair;
  pair.real("k_n", std::nullopt, "normal stiffness").min(0.0, true);
  pair.real("mu", 0.5, "friction coefficient").min(0.0);
  Schema s;
  s.choice<Law>("law", Law::Linear, "contact law");
  s.real("hertz_exponent", 1.5, "the Hertz law's force exponent")
      .only_where("law hertz", [](const Params& p) { return p.choice<Law>("law") == Law::Hertz; });
  s.species_table("species", species, std::nullopt, "the particle species");
  s.pair_table("contacts", "species", pair, std::nullopt, "contact coefficients");
  s.object("walls", walls, "the container's walls");
  Registry r;
  r.add_source<MaterialSource>("materials", "a scene of several materials", s);
  return r;
}

const char* kSpecies = R"([{"name": "small", "diameter": 1, "density": 1.91},
                           {"name": "large", "diameter": 3.16, "density": 13.54}])";
const char* kWalls = R"({"base": {"k_n": 2e5}, "cylinder": {"k_n": 2e5, "mu": 0.1}})";

// A pipeline of the materials source with these parameters (JSON members).
std::string pipeline(const std::string& params) {
  return R"({"name": "t", "source": {"plugin": "materials", "params": {)" + params + "}}}";
}

// The members above with `contacts` and what else is given.
std::string with(const std::string& contacts, const std::string& more = "") {
  return std::string(R"("species": )") + kSpecies + R"(, "walls": )" + kWalls +
         R"(, "contacts": )" + contacts + (more.empty() ? "" : ", " + more);
}

// The parameters the source is made with.
Params made(const std::string& params, const std::vector<std::string>& sets = {}) {
  const Registry r = material_registry();
  const Pipeline p = Pipeline::parse(pipeline(params), "p.json", sets, r);
  Log log;
  log.set_quiet(true);
  made_with.reset();
  p.check(log);
  return made_with.value();
}

std::string error_of(const std::string& params, const std::vector<std::string>& sets = {}) {
  const Registry r = material_registry();
  return test::input_error_of([&] { Pipeline::parse(pipeline(params), "p.json", sets, r); });
}

const char* kAllPairs = R"({"*": {"k_n": 2e5}})";

}  // namespace

TEST(ChoiceParams, ReadBackAsEnums) {
  EXPECT_EQ(made(with(kAllPairs)).choice<Law>("law"), Law::Linear);
  EXPECT_EQ(made(with(kAllPairs, R"("law": "hertz")")).choice<Law>("law"), Law::Hertz);
  EXPECT_EQ(made(with(kAllPairs), {"source.params.law=hertz"}).choice<Law>("law"), Law::Hertz);
  EXPECT_EQ(choice_name(Law::Hertz), "hertz");
}

TEST(ChoiceParams, BadChoiceNamesTheChoicesAndTheClosest) {
  EXPECT_EQ(error_of(with(kAllPairs, R"("law": "herz")")),
            "p.json: source.params.law: expected one of \"linear\", \"hertz\", got \"herz\" (did "
            "you mean "
            "\"hertz\"?)");
  EXPECT_EQ(error_of(with(kAllPairs, R"("law": 1)")),
            "p.json: source.params.law: expected one of \"linear\", \"hertz\", got 1");
}

// A value of a parameter that acts only in another mode was ignored without a word; its
// default is let be, so that a sweep can zip it with the mode.
TEST(ChoiceParams, AValueWhereItHasNoEffectIsRefused) {
  EXPECT_EQ(error_of(with(kAllPairs, R"("hertz_exponent": 2)")),
            "p.json: source.params.hertz_exponent: expected its default 1.5 (it acts only with "
            "law hertz; here law is \"linear\"), got 2");
  EXPECT_EQ(error_of(with(kAllPairs), {"source.params.hertz_exponent=2"}),
            "--set source.params.hertz_exponent=2: expected its default 1.5 (it acts only with "
            "law hertz; here law is \"linear\"), got 2");
  EXPECT_EQ(made(with(kAllPairs, R"("law": "hertz", "hertz_exponent": 2)")).real("hertz_exponent"),
            2.0);
  EXPECT_EQ(made(with(kAllPairs, R"("hertz_exponent": 1.5)")).real("hertz_exponent"), 1.5);
  const Registry r = material_registry();
  const std::string zipped =
      R"({"name": "t", "source": {"plugin": "materials", "params": {)" + with(kAllPairs) +
      R"(}}, "sweep": {"mode": "zip", "parameters": {"source.params.law": ["linear", "hertz"],
                                                     "source.params.hertz_exponent": [1.5, 2]}}})";
  EXPECT_EQ(Pipeline::parse(zipped, "p.json", {}, r).points(), 2u);
}

TEST(ObjectParams, DefaultsAreFilledInside) {
  const Params p = made(with(kAllPairs));
  EXPECT_EQ(p.object("walls").object("base").real("k_n"), 2e5);
  EXPECT_EQ(p.object("walls").object("base").real("mu"), 0.5);  // the default
  EXPECT_EQ(p.object("walls").object("cylinder").real("mu"), 0.1);
  const Registry r = material_registry();
  const std::string resolved =
      Pipeline::parse(pipeline(with(kAllPairs)), "p.json", {}, r).resolved_json();
  EXPECT_NE(resolved.find(R"("base": {
          "k_n": 200000.0,
          "mu": 0.5
        })"),
            std::string::npos)
      << resolved;
}

TEST(ObjectParams, ValuesInsideAreValidatedWithTheirPath) {
  const std::string species =
      std::string(R"("species": )") + kSpecies + R"(, "contacts": )" + kAllPairs;
  EXPECT_EQ(error_of(species + R"(, "walls": {"base": {"k_n": -1}, "cylinder": {"k_n": 1}})"),
            "p.json: source.params.walls.base.k_n: expected a number > 0, got -1");
  EXPECT_EQ(
      error_of(species + R"(, "walls": {"base": {"k_n": 1}})"),
      "p.json: source.params.walls.cylinder.k_n: expected a number > 0, got nothing (required)");
  EXPECT_EQ(
      error_of(species + R"(, "walls": {"base": {"k_n": 1, "muu": 0}, "cylinder": {"k_n": 1}})"),
      "p.json: source.params.walls.base.muu: unknown parameter (did you mean \"mu\"?); known: k_n, "
      "mu");
  EXPECT_EQ(error_of(species + R"(, "walls": {"bse": {}})"),
            "p.json: source.params.walls.bse: unknown parameter (did you mean \"base\"?); known: "
            "base, cylinder");
  EXPECT_EQ(error_of(species + R"(, "walls": [1])"),
            "p.json: source.params.walls: expected an object of parameters, got [1]");
  EXPECT_EQ(error_of(with(kAllPairs), {"source.params.walls.base.k_n=0"}),
            "--set source.params.walls.base.k_n=0: expected a number > 0, got 0");
  // A key that only a --set made is the --set's.
  EXPECT_EQ(error_of(with(kAllPairs), {"source.params.walls.bse.k_n=1"}),
            "--set source.params.walls.bse.k_n=1: source.params.walls.bse: unknown parameter (did "
            "you mean "
            "\"base\"?); known: base, cylinder");
}

TEST(SpeciesParams, ReadInTheirOrder) {
  const SpeciesTable& s = made(with(kAllPairs)).species("species");
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s.name(1), "large");
  EXPECT_EQ(s.find("large"), 1u);
  EXPECT_EQ(s.find("medium"), std::nullopt);
  EXPECT_EQ(s[1].real("density"), 13.54);
  EXPECT_EQ(s.reals("diameter"), (std::vector<double>{1.0, 3.16}));
}

TEST(SpeciesParams, BadEntriesNameTheirIndex) {
  const std::string rest = std::string(R"("walls": )") + kWalls + R"(, "contacts": )" + kAllPairs;
  EXPECT_EQ(error_of(rest + R"(, "species": [{"name": "small", "diameter": 1, "density": 1.91},
                                             {"name": "large", "diameter": 3.16, "density": -13.54}])"),
            "p.json: source.params.species[1].density: expected a number > 0, got -13.54");
  EXPECT_EQ(error_of(rest + R"(, "species": [{"name": "a", "diameter": 1, "density": 1},
                                             {"name": "a", "diameter": 2, "density": 1}])"),
            "p.json: source.params.species[1].name: expected a name no other species has, got "
            "\"a\" again");
  EXPECT_EQ(error_of(rest + R"(, "species": [{"name": "big one", "diameter": 1, "density": 1}])"),
            "p.json: source.params.species[0].name: expected a species name (a letter, then "
            "letters, digits "
            "and _; at most 100), got \"big one\"");
  EXPECT_EQ(error_of(rest + R"(, "species": [{"diameter": 1, "density": 1}])"),
            "p.json: source.params.species[0].name: expected a string, got nothing (required)");
  EXPECT_EQ(error_of(rest + R"(, "species": [])"),
            "p.json: source.params.species: expected a list of species, each an object with a "
            "\"name\", got []");
  EXPECT_EQ(error_of(rest),
            "p.json: source.params.species: expected a list of species, each an object with a "
            "\"name\", got "
            "nothing (required)");
}

TEST(PairParams, EveryPairNeedsAnEntryOrTheStar) {
  EXPECT_EQ(
      error_of(with(R"({"small-small": {"k_n": 1}, "large-large": {"k_n": 1}})")),
      "p.json: source.params.contacts: expected an entry for every pair of species, got none for "
      "\"small-large\" (give it, or \"*\" for the pairs not listed)");
  // Given with "*", a pair takes "*"'s values where it gives none.
  const PairTable& t =
      made(with(R"({"*": {"k_n": 1, "mu": 0.2}, "large-small": {"mu": 0.3}})")).pairs("contacts");
  EXPECT_EQ(t.at(0, 1).real("k_n"), 1.0);
  EXPECT_EQ(t.at(1, 0).real("mu"), 0.3);
  EXPECT_EQ(t.at(1, 1).real("mu"), 0.2);
  // A value neither the pair nor "*" gives, without a default, is missing where it would go.
  EXPECT_EQ(error_of(with(R"({"*": {"mu": 0.1}, "small-large": {"k_n": 1}})")),
            "p.json: source.params.contacts.*.k_n: expected a number > 0, got nothing (required)");
  EXPECT_EQ(error_of(with(
                R"({"small-small": {"k_n": 1}, "large-large": {"k_n": 1}, "small-large": {}})")),
            "p.json: source.params.contacts.small-large.k_n: expected a number > 0, got nothing "
            "(required)");
}

TEST(PairParams, APairIsGivenOnce) {
  EXPECT_EQ(error_of(with(
                R"({"*": {"k_n": 1}, "small-large": {"mu": 0.1}, "large-small": {"mu": 0.9}})")),
            "p.json: source.params.contacts.small-large: expected each pair once (a-b is b-a), got "
            "it also as "
            "\"large-small\"");
}

TEST(PairParams, KeysNameDeclaredSpecies) {
  EXPECT_EQ(error_of(with(R"({"*": {"k_n": 1}, "small-larg": {"mu": 0.1}})")),
            "p.json: source.params.contacts.small-larg: unknown species \"larg\" (did you mean "
            "\"large\"?); "
            "known: small, large");
  EXPECT_EQ(error_of(with(R"({"*": {"k_n": 1}, "small_large": {"mu": 0.1}})")),
            "p.json: source.params.contacts: expected keys \"a-b\" naming two species (of small, "
            "large) or "
            "\"*\", got \"small_large\"");
  EXPECT_EQ(error_of(with(R"({"*": {"k_n": 1}, "sm\nall-large": {}})")),
            "p.json: source.params.contacts: expected keys \"a-b\" naming two species (of small, "
            "large) or "
            "\"*\", got \"sm\\nall-large\"");
  EXPECT_EQ(error_of(with(kAllPairs), {"source.params.contacts.small-larg.mu=1"}),
            "--set source.params.contacts.small-larg.mu=1: source.params.contacts.small-larg: "
            "unknown species "
            "\"larg\" (did you mean \"large\"?); known: small, large");
  EXPECT_EQ(error_of(with(kAllPairs), {"source.params.contacts.small_large.mu=1"}),
            "--set source.params.contacts.small_large.mu=1: source.params.contacts.small_large: "
            "expected keys "
            "\"a-b\" naming two species (of small, large) or \"*\", got \"small_large\"");
  // A table a --set gave whole: its keys are shown quoted only, as the file's.
  EXPECT_EQ(error_of(with(kAllPairs), {R"(source.params.contacts={"*": {"k_n": 1}, "b d!": {}})"}),
            R"(--set source.params.contacts={"*": {"k_n": 1}, "b d!": {}}: expected keys "a-b" )"
            R"(naming two species (of small, large) or "*", got "b d!")");
  EXPECT_EQ(error_of(with(R"({"*": {"k_n": 1}, "small-large": {"mu": -1}})")),
            "p.json: source.params.contacts.small-large.mu: expected a number >= 0, got -1");
  EXPECT_EQ(error_of(with(R"({"*": {"k_n": 1, "m": 0}})")),
            "p.json: source.params.contacts.*.m: unknown parameter (did you mean \"mu\"?); known: "
            "k_n, mu");
}

TEST(PairParams, MatrixOfThreeSpeciesIsSymmetric) {
  const std::string params = R"("walls": )" + std::string(kWalls) + R"(,
    "species": [{"name": "a", "diameter": 1, "density": 1}, {"name": "b", "diameter": 2, "density": 1},
                {"name": "c", "diameter": 3, "density": 1}],
    "contacts": {"*": {"k_n": 1}, "a-b": {"k_n": 2}, "c-b": {"k_n": 3}, "c-c": {"k_n": 4, "mu": 0.1}})";
  const PairTable& t = made(params).pairs("contacts");
  const PairMatrix k = t.matrix("k_n"), mu = t.matrix("mu");
  ASSERT_EQ(k.species(), 3u);
  const double expected[3][3] = {{1, 2, 1}, {2, 1, 3}, {1, 3, 4}};
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < 3; ++j) {
      EXPECT_EQ(k(i, j), expected[i][j]) << i << ", " << j;
      EXPECT_EQ(k.data()[i * 3 + j], expected[i][j]);
      EXPECT_EQ(mu(i, j), i == 2 && j == 2 ? 0.1 : 0.5) << i << ", " << j;
    }
  }
  EXPECT_EQ(t.key(2, 1), "b-c");
  // Set and swept like any value, by the pair's key; the resolved pipeline lists every pair.
  EXPECT_EQ(
      made(params, {"source.params.contacts.c-b.mu=0.25"}).pairs("contacts").matrix("mu")(1, 2),
      0.25);
  EXPECT_EQ(made(params, {"source.params.contacts.*.mu=0.25"}).pairs("contacts").matrix("mu")(0, 0),
            0.25);
  const Registry r = material_registry();
  const std::string resolved = Pipeline::parse(pipeline(params), "p.json", {}, r).resolved_json();
  for (const char* key : {"\"a-a\"", "\"a-b\"", "\"a-c\"", "\"b-b\"", "\"b-c\"", "\"c-c\""})
    EXPECT_NE(resolved.find(key), std::string::npos) << key;
  EXPECT_EQ(resolved.find("\"c-b\""), std::string::npos);
  EXPECT_EQ(resolved.find("\"*\""), std::string::npos);
}

TEST(PairParams, SweptByPath) {
  const Registry r = material_registry();
  const std::string text =
      R"({"name": "t", "source": {"plugin": "materials", "params": {)" + with(kAllPairs) +
      R"(}}, "sweep": {"parameters": {"source.params.contacts.*.mu": [0.0, 0.5],
                                                          "source.params.walls.cylinder.mu": [0.0, 0.1, 0.5]}}})";
  EXPECT_EQ(Pipeline::parse(text, "p.json", {}, r).points(), 6u);
}

TEST(SchemaDeclarations, MistakesOfThePluginAreInternalErrors) {
  Schema species;
  species.real("diameter", 1.0, "diameter");
  Schema s;
  EXPECT_THROW(s.pair_table("contacts", "species", Schema{}, std::nullopt, "no species table yet"),
               InternalError);
  Schema with_name;
  with_name.string("name", std::nullopt, "a second name");
  EXPECT_THROW(s.species_table("species", with_name, std::nullopt, "name is implied"),
               InternalError);
  Schema with_path;
  with_path.path("file", std::string(""), "a file");
  EXPECT_THROW(s.object("o", with_path, "paths are top-level only"), InternalError);
  EXPECT_THROW(s.species_table("species", species, R"([{"name": "a b"}])", "a bad default"),
               InternalError);
  s.species_table("species", species, R"([{"name": "a"}, {"name": "b"}])", "a good default");
  Schema pair;
  pair.real("k_n", std::nullopt, "stiffness");
  EXPECT_THROW(s.pair_table("contacts", "species", pair, R"({"a-a": {"k_n": 1}})", "b-b missing"),
               InternalError);
  s.pair_table("contacts", "species", pair, R"({"*": {"k_n": 1}})", "every pair");
}

// A run's pipeline.json records an optional path's default "" (no file), which was then
// refused as "expected a path to an existing file": the recorded pipeline did not run again.
TEST(PathParams, AnOptionalPathTakesItsEmptyDefaultGivenExplicitly) {
  const std::filesystem::path data =
      std::filesystem::temp_directory_path() / ("granpipe_test_path_" + std::to_string(getpid()));
  std::ofstream(data) << "data";
  Schema s;
  s.path("initial_file", std::string(""), "a start file, or none");
  s.path("data", std::nullopt, "a required file");
  const auto ctx = test::make_context(s, {{"initial_file", ""}, {"data", data.string()}});
  EXPECT_EQ(ctx->params().string("initial_file"), "");
  EXPECT_EQ(test::input_error_of([&] {
              test::make_context(s, {{"data", ""}});
            }),
            "test: params.data: expected a path to an existing file, got \"\"");
  EXPECT_EQ(test::input_error_of([&] {
              test::make_context(s, {{"initial_file", 3}, {"data", data.string()}});
            }),
            "test: params.initial_file: expected a path to an existing file, or \"\" for none, "
            "got 3");
  std::filesystem::remove(data);
}
