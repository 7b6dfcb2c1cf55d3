#!/usr/bin/env bash
# Builds a LAMMPS that loads plugins, from Debian's own source package
# (docs/lammps.md, the supported route): GRANULAR, PLUGIN and MPI (Open MPI),
# shared libraries, nothing else.
#
#   engines/lammps/build_lammps.sh [PREFIX]     (default: build/lammps)
#
# PREFIX receives the install (bin/lmp, lib/liblammps.so) and, in
# PREFIX/source, the extracted source tree, whose src/ holds the headers a
# plugin compiles against.  A finished PREFIX is reused: the script returns at
# once if PREFIX/.complete names the same source package version.
#
# The source comes from `apt-get source lammps`.  Where the machine's apt has
# no deb-src entry, one is derived from its own deb entries (the same hosts,
# suites and components) into /etc/apt/sources.list.d/spinslide-deb-src.sources
# (or .list); no registry host is written anywhere.  Needs root for apt.
set -euo pipefail

root="$(cd "$(dirname "$0")/../.." && pwd -P)"
prefix="${1:-$root/build/lammps}"
case "$prefix" in /*) ;; *) prefix="$PWD/$prefix" ;; esac
jobs="${LAMMPS_JOBS:-$(nproc)}"

have_deb_src() {
  grep -rqsE '^(Types:.*deb-src|deb-src )' /etc/apt/sources.list /etc/apt/sources.list.d/ 2>/dev/null
}

derive_deb_src() {
  local d=/etc/apt/sources.list.d
  for f in "$d"/*.sources; do
    [ -e "$f" ] || continue
    case "$f" in *spinslide-deb-src.sources) continue ;; esac
    # deb822 stanzas: the same entries with Types: deb-src.
    sed -n 's/^Types:[[:space:]]*deb$/Types: deb-src/; p' "$f"
    echo
  done >"$d/spinslide-deb-src.sources"
  if [ -f /etc/apt/sources.list ]; then
    sed -n 's/^deb \(.*\)$/deb-src \1/p' /etc/apt/sources.list >"$d/spinslide-deb-src.list"
  fi
  echo "build_lammps: derived deb-src entries from the machine's apt sources"
}

echo "build_lammps: prefix $prefix"
if ! have_deb_src; then derive_deb_src; fi
apt-get update -qq
apt-get install -y -qq dpkg-dev xz-utils cmake g++ libopenmpi-dev openmpi-bin >/dev/null

version="$(apt-cache showsrc lammps | sed -n 's/^Version: //p' | head -1)"
if [ -z "$version" ]; then
  echo "build_lammps: FAILED: apt knows no source package 'lammps'" >&2
  exit 1
fi
if [ -f "$prefix/.complete" ] && [ "$(cat "$prefix/.complete")" = "$version" ]; then
  echo "build_lammps: LAMMPS $version already built in $prefix"
  exit 0
fi

rm -rf "$prefix"
mkdir -p "$prefix/download"
(cd "$prefix/download" && apt-get source -qq lammps >/dev/null 2>&1 || apt-get source lammps)
source_dir="$(find "$prefix/download" -mindepth 1 -maxdepth 1 -type d -name 'lammps-*' | head -1)"
if [ -z "$source_dir" ]; then
  echo "build_lammps: FAILED: apt-get source lammps gave no source tree" >&2
  exit 1
fi
mv "$source_dir" "$prefix/source"
rm -rf "$prefix/download"

start=$SECONDS
cmake -S "$prefix/source/cmake" -B "$prefix/build" \
  -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_INSTALL_PREFIX="$prefix" -DCMAKE_INSTALL_RPATH="$prefix/lib" \
  -DBUILD_SHARED_LIBS=on -DBUILD_MPI=on -DBUILD_OMP=off \
  -DLAMMPS_EXCEPTIONS=on \
  -DPKG_GRANULAR=on -DPKG_PLUGIN=on \
  -DBUILD_DOC=off -DBUILD_TOOLS=off -DBUILD_LAMMPS_SHELL=off \
  -DWITH_JPEG=off -DWITH_PNG=off -DWITH_FFMPEG=off -DWITH_GZIP=off >"$prefix/configure.log"
cmake --build "$prefix/build" -j "$jobs" >"$prefix/build.log"
cmake --install "$prefix/build" >"$prefix/install.log"
echo "$version" >"$prefix/.complete"
echo "build_lammps: LAMMPS $version built in $((SECONDS - start)) s: $prefix/bin/lmp"
