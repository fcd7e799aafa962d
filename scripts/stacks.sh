# The Debian stacks the module is built and tested on besides the machine's own
# (sourced by scripts/common.sh). Each is a debootstrap root from Debian's
# registry, cached outside the clone and made again when missing or stale:
#
#   host     the machine itself: Debian 12, VTK 9.1, ParaView 5.11
#   trixie   Debian 13: VTK 9.3, ParaView 5.13, PyVista 0.44
#   sid      Debian unstable: VTK 9.6, ParaView 6.1, PyVista 0.49
#
# A root holds the packages of every step that runs in it (build, tests,
# ParaView, PyVista); the repository is bind-mounted at its own path inside, so
# a stack's build folder (build-<stack>) works from either side.

STACK_CACHE="${SHADOWMAPS_STACK_CACHE:-/var/cache/vtkshadowmaps/stacks}"

# The Debian archive the machine's own apt uses: the first URI of a "deb"
# source (one-line .list files and deb822 .sources files) whose path ends in
# /debian, skipping comments and snapshot archives (frozen in time, they hold
# neither trixie nor sid as they are now). Prints "URI FILE", or nothing.
#   machine_mirror [APT_DIR]   (default /etc/apt)
machine_mirror() {
  local file sources="${1:-/etc/apt}"
  for file in "$sources/sources.list" "$sources"/sources.list.d/*.list \
    "$sources"/sources.list.d/*.sources; do
    [ -r "$file" ] || continue
    awk '
      function flush() {
        if (types ~ /(^|[ \t])deb([ \t]|$)/ && !disabled) printf "%s", uris
        types = ""; uris = ""; disabled = 0
      }
      /^[ \t]*#/ { next }
      { sub(/#.*/, "") }
      /^[ \t]*$/ { flush(); next }                  # a deb822 stanza ends
      tolower($1) == "types:" { types = $0 }
      tolower($1) == "uris:" { for (i = 2; i <= NF; ++i) uris = uris $i "\n" }
      tolower($1) == "enabled:" && tolower($2) == "no" { disabled = 1 }
      $1 == "deb" {                                   # one-line: deb [options] URI suite ...
        for (i = 2; i <= NF; ++i) if ($i !~ /^\[/ && $i !~ /=/ && $i !~ /\]$/) { print $i; break }
      }
      END { flush() }
    ' "$file" | grep -v "snapshot\." | grep -E "/debian/?$" | head -1 | sed "s|/$||; s|\$| $file|"
  done | head -1
}

if [ -n "${SHADOWMAPS_STACK_MIRROR:-}" ]; then
  STACK_MIRROR="$SHADOWMAPS_STACK_MIRROR"
  STACK_MIRROR_SOURCE="SHADOWMAPS_STACK_MIRROR"
else
  read -r STACK_MIRROR STACK_MIRROR_SOURCE <<< "$(machine_mirror)" || true
fi
# A root older than this is made again (its suite has moved on).
STACK_MAX_AGE_DAYS="${SHADOWMAPS_STACK_MAX_AGE_DAYS:-30}"
# The exit status of a step that failed because Debian's archive could not
# serve a root (not the project's failure).
STACK_UNAVAILABLE=75

# The packages inside a root: the module's build and tests, then the ParaView
# plugin's and PyVista's. In trixie, as on the host, python3-paraview conflicts
# with python3-vtk9, so scripts/paraview.sh swaps them there too.
stack_packages() {
  local packages=(
    cmake ninja-build g++ pkg-config git ca-certificates
    libvtk9-dev python3-vtk9 python3-dev
    libglm-dev libopenimageio-dev openimageio-tools python3-imath
    libgtest-dev libembree-dev assimp-testmodels
    xvfb xauth libgl1-mesa-dri
    paraview paraview-dev openmpi-bin libprotobuf-dev
    python3-pyvista)
  [ "$1" = sid ] && packages+=(python3-paraview)
  printf '%s\n' "${packages[@]}"
}

stack_root() { echo "$STACK_CACHE/$1"; }

# What a root was made from: a root whose stamp differs is stale.
stack_stamp() {
  { echo "suite $1"; echo "mirror $STACK_MIRROR"; stack_packages "$1"; } | sha256sum | cut -c1-16
}

stack_is_fresh() {
  local root
  root="$(stack_root "$1")"
  [ -f "$root/.shadowmaps-stamp" ] &&
    [ "$(cat "$root/.shadowmaps-stamp")" = "$(stack_stamp "$1")" ] &&
    [ -z "$(find "$root/.shadowmaps-stamp" -mtime +"$STACK_MAX_AGE_DAYS")" ]
}

# Makes the root of a stack unless a fresh one is cached. Returns
# STACK_UNAVAILABLE only when Debian's archive could not serve it (debootstrap
# or apt could not fetch); any other failure (no such stack, not root, a
# package the list names wrongly) returns 1, a failure of the project's. A
# stale root whose remaking the archive refuses is used as it is, with a warning.
ensure_stack() {
  local name="$1" root building status=0
  case "$name" in
    trixie | sid) ;;
    *) echo "No stack '$name': host, trixie or sid" >&2; return 1 ;;
  esac
  if [ "$(id -u)" -ne 0 ]; then
    echo "The $name stack needs root (debootstrap, chroot and mount namespaces)" >&2
    return 1
  fi
  if [ -z "${STACK_MIRROR:-}" ]; then
    echo "No Debian archive in this machine's apt sources (/etc/apt/sources.list," \
      "/etc/apt/sources.list.d/): set SHADOWMAPS_STACK_MIRROR to one (its URI, ending in /debian)" >&2
    return 1
  fi
  root="$(stack_root "$name")"
  stack_is_fresh "$name" && return 0
  command -v debootstrap >/dev/null || install_missing_packages debootstrap
  building="$root.building"
  SECONDS=0
  echo "Making the $name root in $root (debootstrap, then $(stack_packages "$name" | wc -l) packages)"
  echo "Debian archive: $STACK_MIRROR (from $STACK_MIRROR_SOURCE)"
  rm -rf "$building"
  mkdir -p "$STACK_CACHE"
  make_stack_root "$name" "$building" > "$building.log" 2>&1 || status=$?
  if [ "$status" -ne 0 ]; then
    tail -20 "$building.log"
    if [ "$status" -eq "$STACK_UNAVAILABLE" ] && [ -f "$root/.shadowmaps-stamp" ]; then
      echo "WARNING: the $name root could not be made again; using the one from" \
        "$(date -r "$root/.shadowmaps-stamp" +%F)" >&2
      return 0
    fi
    return "$status"
  fi
  stack_stamp "$name" > "$building/.shadowmaps-stamp"
  rm -rf "$root"
  mv "$building" "$root"
  echo "Made the $name root in $SECONDS s"
}

# debootstrap, then the stack's packages. Fetch failures are the archive's
# (STACK_UNAVAILABLE); a package apt does not know is the project's (1).
make_stack_root() {
  local name="$1" building="$2" output
  debootstrap --variant=minbase "$name" "$building" "$STACK_MIRROR" || return "$STACK_UNAVAILABLE"
  # sid's snapshot has an expired Release file; apt inside the root (here and
  # in scripts/paraview.sh) must accept it.
  echo 'Acquire::Check-Valid-Until "false";' > "$building/etc/apt/apt.conf.d/99shadowmaps-snapshot"
  chroot_with_mounts "$building" apt-get update -qq || return "$STACK_UNAVAILABLE"
  output="$(chroot_with_mounts "$building" env DEBIAN_FRONTEND=noninteractive apt-get \
    -y -qq --no-install-recommends install $(stack_packages "$name") 2>&1)" && return 0
  echo "$output"
  if grep -q "Unable to locate package\|has no installation candidate\|unmet dependencies" <<< "$output"; then
    return 1
  fi
  return "$STACK_UNAVAILABLE"
}

# Runs a command chrooted into a root, with /proc, /sys (MPI's transports and
# hwloc read it), /dev, a fresh /tmp and the repository (at its own path)
# mounted in a mount namespace of its own: the mounts end with the command, and
# two commands in one root do not unmount each other's.
#   chroot_with_mounts ROOT COMMAND...
chroot_with_mounts() {
  local root="$1"
  shift
  unshare --mount --propagation private bash -c '
    root="$1" repository="$2"
    shift 2
    # The repository may lie under /tmp: its mount point is made on the tmpfs.
    mount -t proc proc "$root/proc" &&
      mount --rbind /sys "$root/sys" &&
      mount --rbind /dev "$root/dev" &&
      mount -t tmpfs tmpfs "$root/tmp" &&
      mkdir -p "$root$repository" &&
      mount --bind "$repository" "$root$repository" || exit 1
    exec chroot "$root" "$@"' chroot_with_mounts "$root" "$ROOT" "$@"
}

# Runs a command inside a stack's root, in the repository, as the same script
# would run on the host: in_stack sid bash scripts/test_stack.sh
in_stack() {
  local name="$1"
  shift
  chroot_with_mounts "$(stack_root "$name")" \
    env -i PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
    HOME=/root LANG=C.UTF-8 CI="${CI:-}" SHADOWMAPS_STACK="$name" SHADOWMAPS_IN_STACK=1 \
    SHADOWMAPS_UPDATE_BASELINES="${SHADOWMAPS_UPDATE_BASELINES:-}" \
    SHADOWMAPS_SKIP_PARAVIEW="${SHADOWMAPS_SKIP_PARAVIEW:-}" \
    SHADOWMAPS_MATRIX_DIR="$MATRIX_DIR" \
    bash -c 'cd "$0" && exec "$@"' "$ROOT" "$@"
}

# Where each stack's tests leave their row of the matrix (scripts/test_stack.sh).
MATRIX_DIR="${SHADOWMAPS_MATRIX_DIR:-$ROOT/build-matrix}"

stack_unavailable() {
  cat <<MESSAGE >&2

!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!
!!! STACK $1 UNAVAILABLE: Debian's archive could not serve its root (see
!!! $(stack_root "$1").building.log). This is not a failure of the project's;
!!! its tests did not run on $1.
!!! Archive: ${STACK_MIRROR:-none} (from ${STACK_MIRROR_SOURCE:-no apt source}).
!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!

MESSAGE
}

# Prints the matrix of the given stacks and a closing "N passed, N failed"
# line; fails when a stack failed a test or left no row.
print_matrix() {
  local stack row passed=0 failed=0 status=0
  local name vtk paraview pyvista stack_passed stack_failed notes
  echo
  printf '%-8s %-8s %-10s %-8s %7s %7s  %s\n' stack VTK ParaView PyVista passed failed notes
  for stack in "$@"; do
    row="$MATRIX_DIR/$stack.row"
    if [ ! -f "$row" ]; then
      printf '%-8s %-8s %-10s %-8s %7s %7s  %s\n' "$stack" - - - 0 1 "no result"
      failed=$((failed + 1))
      status=1
      continue
    fi
    IFS=$'\t' read -r name vtk paraview pyvista stack_passed stack_failed notes < "$row"
    printf '%-8s %-8s %-10s %-8s %7s %7s  %s\n' "$name" "$vtk" "$paraview" "$pyvista" \
      "$stack_passed" "$stack_failed" "$notes"
    passed=$((passed + stack_passed))
    failed=$((failed + stack_failed))
    [ "$stack_failed" -eq 0 ] || status=1
  done
  echo
  echo "matrix: $passed passed, $failed failed"
  return "$status"
}
