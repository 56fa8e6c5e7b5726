#!/usr/bin/env bash
# The layer library as the loader sees it: exactly one exported symbol, xrNegotiateLoaderApiLayerInterface,
# and no shared libraries beyond the C/C++ runtime (libvulkan is dlopen'ed by the compute backend and the
# OpenXR loader is never linked). Sanitizer runtimes (GCC's, clang's shared ASan runtime) are allowed.
# Usage: check_library.sh LIBRARY
set -euo pipefail
lib=$1
exports=$(nm -D --defined-only "$lib" | awk '{print $3}' | sort)
if [ "$exports" != "xrNegotiateLoaderApiLayerInterface" ]; then
  echo "unexpected exports of $lib:"; echo "$exports"; exit 1
fi
allowed='^(libc\.so\.6|libm\.so\.6|libstdc\+\+\.so\.6|libgcc_s\.so\.1|libpthread\.so\.0|libdl\.so\.2|ld-linux-x86-64\.so\.2|libasan\.so\.[0-9]+|libubsan\.so\.[0-9]+|libclang_rt\.asan-x86_64\.so)$'
bad=0
while read -r needed; do
  if ! [[ $needed =~ $allowed ]]; then echo "unexpected dependency of $lib: $needed"; bad=1; fi
done < <(readelf -d "$lib" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p')
[ $bad -eq 0 ] || exit 1
echo "$lib: exports only xrNegotiateLoaderApiLayerInterface; needs $(readelf -d "$lib" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p' | tr '\n' ' ')"
