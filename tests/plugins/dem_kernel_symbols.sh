#!/usr/bin/env bash
# dem_kernel_symbols.sh NM ARCHIVE
# The dem kernels compiled for AVX2 and AVX-512 must define no symbol the linker may merge
# with a copy from another object (weak or unique: inline functions and templates left out
# of line). Merged, one copy serves every caller, and baseline code could end up calling
# AVX-512 instructions on a processor without them. Their entry points live in namespaces
# of their own (kernels.hpp); anything else the compiler emits out of line must be internal.
set -euo pipefail
nm=$1 archive=$2
symbols=$("$nm" --defined-only -A "$archive")
shared=$(echo "$symbols" |
  awk '$1 ~ /kernels_(avx2|avx512)\.cpp\.o:/ && $2 ~ /^[WVu]$/ && $3 != "DW.ref.__gxx_personality_v0"')
if [ -n "$shared" ]; then
  echo "FAIL: the wide kernels define symbols the linker may merge with other copies:"
  echo "$shared" | c++filt
  exit 1
fi
echo "$symbols" | grep 'kernels_avx2\.cpp\.o:.* T .*avx2.*select_kernels' >/dev/null ||
  { echo "FAIL: no AVX2 kernels in $archive"; exit 1; }
