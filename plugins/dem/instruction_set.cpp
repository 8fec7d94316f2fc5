#include "instruction_set.hpp"

#include <cstdlib>

#include "granpipe/errors.hpp"

namespace granpipe::dem {

namespace {

constexpr InstructionSet kPaths[] = {InstructionSet::Baseline, InstructionSet::Avx2,
                                     InstructionSet::Avx512};

bool compiled(InstructionSet set) {
  switch (set) {
    case InstructionSet::Baseline:
      return true;
    case InstructionSet::Avx2:
#ifdef GRANPIPE_DEM_HAS_AVX2
      return true;
#else
      return false;
#endif
    case InstructionSet::Avx512:
#ifdef GRANPIPE_DEM_HAS_AVX512
      return true;
#else
      return false;
#endif
    case InstructionSet::Auto:
      break;
  }
  return false;
}

// The levels the paths are compiled for (-march=x86-64-v3 and -v4), as the processor
// reports them.
bool processor_runs(InstructionSet set) {
  switch (set) {
    case InstructionSet::Baseline:
      return true;
#if defined(__x86_64__)
    case InstructionSet::Avx2:
      return __builtin_cpu_supports("x86-64-v3");
    case InstructionSet::Avx512:
      return __builtin_cpu_supports("x86-64-v4");
#else
    case InstructionSet::Avx2:
    case InstructionSet::Avx512:
      return false;
#endif
    case InstructionSet::Auto:
      break;
  }
  return false;
}

std::string choices() {
  std::string names = name_of(InstructionSet::Auto);
  for (InstructionSet set : kPaths) names += std::string(", ") + name_of(set);
  return names;
}

InstructionSet named_in_environment() {
  const char* value = std::getenv("GRANPIPE_DEM_INSTRUCTION_SET");
  if (value == nullptr || *value == '\0') return InstructionSet::Auto;
  for (InstructionSet set : {InstructionSet::Auto, InstructionSet::Baseline, InstructionSet::Avx2,
                             InstructionSet::Avx512}) {
    if (std::string(value) == name_of(set)) return set;
  }
  throw InputError("GRANPIPE_DEM_INSTRUCTION_SET: expected one of " + choices() + ", found \"" +
                   value + "\"");
}

}  // namespace

const char* name_of(InstructionSet set) {
  switch (set) {
    case InstructionSet::Baseline:
      return "baseline";
    case InstructionSet::Avx2:
      return "avx2";
    case InstructionSet::Avx512:
      return "avx512";
    case InstructionSet::Auto:
      break;
  }
  return "auto";
}

const char* label_of(InstructionSet set) {
  switch (set) {
    case InstructionSet::Avx2:
      return "AVX2";
    case InstructionSet::Avx512:
      return "AVX-512";
    default:
      return name_of(set);
  }
}

int doubles_per_vector(InstructionSet set) {
  switch (set) {
    case InstructionSet::Avx2:
      return 4;
    case InstructionSet::Avx512:
      return 8;
    default:
      return 2;  // SSE2, the x86-64 baseline
  }
}

bool runs_here(InstructionSet set) { return compiled(set) && processor_runs(set); }

InstructionSet resolve(InstructionSet requested, const std::string& what) {
  // Read (and a bad value refused) whatever the request: a mistyped variable left in the
  // environment would otherwise pass unnoticed while the runs name their paths.
  const InstructionSet environment = named_in_environment();
  if (requested == InstructionSet::Auto) {
    requested = environment;
    if (requested != InstructionSet::Auto)
      return resolve(requested, "GRANPIPE_DEM_INSTRUCTION_SET");
    InstructionSet widest = InstructionSet::Baseline;
    for (InstructionSet set : kPaths) {
      if (runs_here(set)) widest = set;
    }
    return widest;
  }
  if (!compiled(requested)) {
    throw InputError(
        what + ": expected an instruction set this build has (" + std::string(label_of(requested)) +
        " was not compiled: the compiler does not know it), found \"" + name_of(requested) + "\"");
  }
  if (!processor_runs(requested)) {
    throw InputError(what + ": expected an instruction set this processor runs, found \"" +
                     name_of(requested) + "\" (" + label_of(requested) +
                     " is missing here; \"auto\" takes the widest it has)");
  }
  return requested;
}

}  // namespace granpipe::dem
