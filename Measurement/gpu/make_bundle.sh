#!/bin/bash
# Packs what `vtkshadows speed` needs on a GPU machine that has no VTK and no
# display (the device machine of docs/notes/many-actors.md, "On a GPU"): the program
# and this build's module, the VTK and system libraries they load, an Xvfb
# with Mesa's GLX for it to serve, and xkbcomp with its keymaps. Clients then
# take the NVIDIA driver's GLX (run_on_gpu.sh). Embree and ICU's data, which
# speed never uses, are replaced by stand-ins so that the bundle stays under
# the device's 64 MiB.
#
#   Measurement/gpu/make_bundle.sh [BUILD_DIR [OUT_DIR]]   (default build, .gpu)
#
# writes OUT_DIR/bundle.tar.xz; OUT_DIR should be ignored by git
# (echo /.gpu/ >> .git/info/exclude). Made on Debian 12 with Embree 3; the GPU
# machine's C and C++ runtimes, which are not bundled, must be at least as new.
set -euo pipefail
for needed in /usr/bin/Xvfb /usr/bin/xkbcomp /usr/lib/x86_64-linux-gnu/dri/swrast_dri.so; do
  [ -e "$needed" ] || { echo "make_bundle.sh: $needed is missing (packages xvfb, x11-xkb-utils, libgl1-mesa-dri)" >&2; exit 1; }
done
here="$(cd "$(dirname "$0")" && pwd)"
build="$(cd "${1:-build}" && pwd)"
out="$(mkdir -p "${2:-.gpu}" && cd "${2:-.gpu}" && pwd)"
stage="$(mktemp -d)"
trap 'rm -rf "$stage"' EXIT
mkdir -p "$stage/bin" "$stage/lib" "$stage/dri"
dri=/usr/lib/x86_64-linux-gnu/dri/swrast_dri.so
cp "$build/bin/vtkshadows" /usr/bin/Xvfb /usr/bin/xkbcomp "$stage/bin/"
cp "$here/run_on_gpu.sh" "$stage/"
cp "$dri" "$stage/dri/"
cp -rL /usr/share/X11/xkb "$stage/xkb"
# The C library and the compiler's runtime are the machine's own.
skip='^(linux-vdso|libc\.so|libm\.so|libstdc\+\+|libgcc_s|ld-linux|libpthread|libdl\.so|librt\.so|libembree3|libicudata)'
loaded="$stage/ldd.txt"
for file in "$build/bin/vtkshadows" /usr/bin/Xvfb /usr/bin/xkbcomp "$dri" \
  /usr/lib/x86_64-linux-gnu/libGLX_mesa.so.0; do
  ldd "$file" >> "$loaded"
done
if grep -q "not found" "$loaded"; then
  echo "make_bundle.sh: libraries not found here:" >&2
  grep "not found" "$loaded" >&2
  exit 1
fi
awk '{print $1, $3}' "$loaded" | grep -vE "$skip" | awk '$2 ~ /^\// {print $2}' | sort -u |
  while read -r lib; do cp -L "$lib" "$stage/lib/"; done
rm "$loaded"
cp -L /usr/lib/x86_64-linux-gnu/libGLX_mesa.so.0 "$stage/lib/"
gcc -shared -fPIC -Wl,-soname,libembree3.so.3 -o "$stage/lib/libembree3.so.3" "$here/embree_stand_in.c"
icu="$(ldd "$dri" | grep -o 'libicudata\.so\.[0-9]*' | head -n 1 || true)"
if [ -n "$icu" ]; then
  gcc -shared -fPIC -Wl,-soname,"$icu" -DICU_DATA="icudt${icu##*.}_dat" -o "$stage/lib/$icu" \
    "$here/icu_data_stand_in.c"
fi
tar -C "$stage" -cf - . | xz -T0 -6 > "$out/bundle.tar.xz"
ls -l "$out/bundle.tar.xz"
