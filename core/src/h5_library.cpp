// HDF5's own clean-up at process exit closes whatever is still open. granpipe closes
// every HDF5 object itself, so what is still open at exit is an object whose close
// failed (on a full disk), and HDF5 1.10 crashes closing it a second time: the clean-up
// is switched off before the library is first used.
#include <hdf5.h>

namespace granpipe::h5 {
namespace {

[[maybe_unused]] const bool no_cleanup_at_exit = [] {
  H5dont_atexit();
  return true;
}();

}  // namespace
}  // namespace granpipe::h5
