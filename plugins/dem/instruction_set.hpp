#pragma once
// The instruction sets the force and integration loops are compiled for. kernels.cpp is
// compiled once for each that the compiler knows (CMakeLists.txt) and the engine picks one
// when it starts, so one build runs on any x86-64 processor at the fastest path it has, and
// the tests run every path the test machine has. The paths give the same physics, not the
// same bits: fused multiply-adds round differently (a run is bit-identical only on one path).
#include <string>

namespace granpipe::dem {

enum class InstructionSet { Auto, Baseline, Avx2, Avx512 };

// "auto", "baseline", "avx2", "avx512": the names of the dem source's instruction_set and
// of GRANPIPE_DEM_INSTRUCTION_SET.
const char* name_of(InstructionSet set);
// "baseline", "AVX2", "AVX-512": how run.log and the benchmarks name the path that ran.
const char* label_of(InstructionSet set);

// The path's width, in doubles per vector of the force loops: 2 (baseline), 4, 8.
int doubles_per_vector(InstructionSet set);

// Whether this build has the path and this processor runs it.
bool runs_here(InstructionSet set);

// The path a run takes: an explicit request as it is (InputError, naming `what`, when it
// cannot run here); Auto the one GRANPIPE_DEM_INSTRUCTION_SET names, if set (how tests and
// benchmarks force a path without editing pipelines), else the widest that runs here. A
// value of GRANPIPE_DEM_INSTRUCTION_SET that names no path is refused whatever `requested`.
InstructionSet resolve(InstructionSet requested, const std::string& what);

}  // namespace granpipe::dem
