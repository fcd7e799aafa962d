#!/usr/bin/env bash
# The stacks' Debian archive comes from the machine's own apt sources
# (scripts/stacks.sh, machine_mirror), SHADOWMAPS_STACK_MIRROR overrides it,
# and no file of the repository names a package registry's host.
#   test_stack_mirror.sh REPOSITORY
set -u
ROOT="$1"
failures=0
check() {
  if [ "$2" = "$3" ]; then echo "ok   $1"; else echo "FAIL $1: '$2', expected '$3'"; failures=$((failures + 1)); fi
}
source "$ROOT/scripts/stacks.sh"

apt="$(mktemp -d)"
trap 'rm -rf "$apt"' EXIT
mkdir -p "$apt/sources.list.d"

# One-line sources: comments, options, a snapshot archive, the security archive.
cat > "$apt/sources.list" <<'SOURCES'
# deb http://commented.example/debian bookworm main
deb [arch=amd64 signed-by=/usr/share/keyrings/k.gpg] http://snapshot.example/archive/debian/20250520T000000Z bookworm main
deb http://security.example/debian-security bookworm-security main
deb http://one-line.example/debian/ bookworm main
SOURCES
check "one-line sources" "$(machine_mirror "$apt")" "http://one-line.example/debian $apt/sources.list"

# deb822 sources: a comment inside a stanza, URIs before Types, deb-src and
# disabled stanzas skipped.
rm "$apt/sources.list"
cat > "$apt/sources.list.d/debian.sources" <<'SOURCES'
Types: deb-src
URIs: http://sources-only.example/debian

Types: deb
Enabled: no
URIs: http://disabled.example/debian

URIs: http://security.example/debian-security http://deb822.example/debian
# http://snapshot.example/archive/debian/20250520T000000Z
Types: deb
Suites: bookworm
SOURCES
check "deb822 sources" "$(machine_mirror "$apt")" \
  "http://deb822.example/debian $apt/sources.list.d/debian.sources"

rm "$apt/sources.list.d/debian.sources"
check "no Debian archive" "$(machine_mirror "$apt")" ""

check "the override" "$(SHADOWMAPS_STACK_MIRROR=http://override.example/debian bash -c \
  "source '$ROOT/scripts/stacks.sh'; echo \"\$STACK_MIRROR \$STACK_MIRROR_SOURCE\"")" \
  "http://override.example/debian SHADOWMAPS_STACK_MIRROR"

# Registry hosts, written so that this file does not name them itself.
hosts='deb[.]debian[.]org|snapshot[.]debian[.]org|ftp[.][a-z]+[.]debian[.]org|security[.]debian[.]org|pypi[.]org|pythonhosted[.]org|archive[.]ubuntu[.]com'
files="$(git -C "$ROOT" ls-files | wc -l)"
check "the repository's files are listed" "$([ "$files" -gt 100 ] && echo yes)" yes
named="$(cd "$ROOT" && git ls-files -z | xargs -0 grep -lE "$hosts")"
check "no file of the repository names a registry's host" "$named" ""

echo "$failures failures"
[ "$failures" -eq 0 ]
