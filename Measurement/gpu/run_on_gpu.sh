#!/bin/bash
# Inside the bundle (make_bundle.sh), unpacked at /tmp/b on the GPU machine,
# as root: runs "$@" with a display whose clients render on the GPU. Xvfb's
# own GLX is Mesa's; the clients' GLX is the NVIDIA driver's (glvnd's vendor
# override), which is what makes them render on the GPU.
B=/tmp/b
cp $B/bin/xkbcomp /usr/bin/xkbcomp
mkdir -p /usr/share/X11 /usr/lib/x86_64-linux-gnu/dri
[ -d /usr/share/X11/xkb ] || cp -r $B/xkb /usr/share/X11/xkb
cp $B/dri/swrast_dri.so /usr/lib/x86_64-linux-gnu/dri/
# One server for every call: without -noreset it would reset, and lose its
# GLX, when its last client leaves (a second speed run then found it gone).
if [ ! -e /tmp/.X11-unix/X99 ]; then
  LD_LIBRARY_PATH=$B/lib $B/bin/Xvfb :99 -screen 0 1920x1080x24 -nolisten tcp -noreset \
    > /tmp/xvfb.log 2>&1 &
  sleep 3
fi
NVIDIA=$(ls -d /usr/local/nvidia/lib64 /usr/local/nvidia/lib 2>/dev/null | tr '\n' ':')
export LD_LIBRARY_PATH=$B/lib:$NVIDIA DISPLAY=:99 __GLX_VENDOR_LIBRARY_NAME=nvidia
exec "$@"
