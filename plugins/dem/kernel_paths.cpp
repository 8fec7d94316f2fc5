#include <string>

#include "granpipe/errors.hpp"
#include "kernels.hpp"

namespace granpipe::dem {

Kernels select_kernels(InstructionSet path, ContactLaw law, bool friction, bool rotation,
                       bool rolling) {
  if (!runs_here(path)) {
    throw InternalError(std::string("dem: kernels asked for on a path that does not run here: ") +
                        name_of(path));
  }
  switch (path) {
#ifdef GRANPIPE_DEM_HAS_AVX512
    case InstructionSet::Avx512:
      return avx512::select_kernels(law, friction, rotation, rolling);
#endif
#ifdef GRANPIPE_DEM_HAS_AVX2
    case InstructionSet::Avx2:
      return avx2::select_kernels(law, friction, rotation, rolling);
#endif
    default:
      return baseline::select_kernels(law, friction, rotation, rolling);
  }
}

}  // namespace granpipe::dem
