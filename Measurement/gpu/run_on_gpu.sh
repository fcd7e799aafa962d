#!/bin/bash
# Inside the bundle (make_bundle.sh), unpacked at /tmp/b on the GPU machine,
# as root: runs "$@" with a display whose clients render on the GPU. Xvfb's
# own GLX is Mesa's; the clients' GLX is the NVIDIA driver's (glvnd's vendor
# override), which is what makes them render on the GPU. It installs xkbcomp,
# the keymaps and Mesa's driver where Xvfb looks for them, and stops any Xvfb
# running: for a bare machine that is given back after the run, not for one's own.
B=/tmp/b
cp $B/bin/xkbcomp /usr/bin/xkbcomp
mkdir -p /usr/share/X11 /usr/lib/x86_64-linux-gnu/dri
[ -d /usr/share/X11/xkb ] || cp -r $B/xkb /usr/share/X11/xkb
cp $B/dri/swrast_dri.so /usr/lib/x86_64-linux-gnu/dri/
# A fresh server for every call: one that outlived its client has been seen to
# drop the next client's connection at its start (and without -noreset it
# would reset and lose its GLX when its last client leaves).
pkill -x Xvfb
for _ in $(seq 100); do pgrep -x Xvfb > /dev/null || break; sleep 0.1; done
pkill -9 -x Xvfb
rm -f /tmp/.X99-lock /tmp/.X11-unix/X99
LD_LIBRARY_PATH=$B/lib $B/bin/Xvfb :99 -screen 0 1920x1080x24 -nolisten tcp -noreset \
  > /tmp/xvfb.log 2>&1 &
for _ in $(seq 50); do [ -e /tmp/.X11-unix/X99 ] && break; sleep 0.2; done
[ -e /tmp/.X11-unix/X99 ] || { echo "Xvfb did not start:" >&2; cat /tmp/xvfb.log >&2; exit 1; }
NVIDIA=$(ls -d /usr/local/nvidia/lib64 /usr/local/nvidia/lib 2>/dev/null | paste -sd: -)
export LD_LIBRARY_PATH=$B/lib${NVIDIA:+:$NVIDIA} DISPLAY=:99 __GLX_VENDOR_LIBRARY_NAME=nvidia
exec "$@"
