#!/usr/bin/env bash
# Builds CalculiX 2.20 (Debian's calculix-ccx 2.20-1 source, Debian's patches and flags) with
# *FRICTION, USER served by this library, and leaves the executable OUTDIR/ccx.
#
#   hosts/calculix/build.sh OUTDIR [--source calculix-ccx_2.20.orig.tar.bz2]
#
# No CalculiX source is kept in this repository: the source package is fetched (apt-get source
# --download-only, with a private apt configuration holding deb-src entries derived from the
# machine's deb822 sources when it has none), its checksums verified against the pins below,
# Debian's patch series applied, then our edit script (edit.sh, edits/) inserts calls to our
# routines (src/) at places found by short anchors. The executable is CalculiX's, under the
# GPL (docs/calculix.md).
#
# Cache (INTERFACIAL_CCX_CACHE, default ~/.cache/interfacial/ccx):
#   src/                     the two Debian tarballs
#   stock-<hash>/            the patched source built with Debian's flags, keyed by the
#                            tarballs, the flags and this script's stock stage
#   build-<hash>/            the edited files, our objects and the executable, keyed by the
#                            stock key, the edits, our sources and the library archive
# A second run with nothing changed only runs cargo (a no-op) and copies the executable.
set -euo pipefail
t_start=$(date +%s)
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)

usage() { echo "usage: $0 OUTDIR [--source calculix-ccx_2.20.orig.tar.bz2]" >&2; exit 2; }
[ $# -ge 1 ] || usage
outdir=$1
shift
given_source=
while [ $# -gt 0 ]; do
  case "$1" in
    --source) [ $# -ge 2 ] || usage; given_source=$(realpath "$2"); shift 2 ;;
    *) usage ;;
  esac
done

# Pins: Debian bookworm's calculix-ccx 2.20-1 (the .dsc's Checksums-Sha256).
orig=calculix-ccx_2.20.orig.tar.bz2
orig_sha=b9a6075e181a777bbcfadd3ad21a70749dfdbb439373df3b4895cd2f438343ab
deb=calculix-ccx_2.20-1.debian.tar.xz
deb_sha=befe7a566836c2527aced457dfcf3bb6cfe69737915b795a99c821694426b5c9
# Debian's flags: debian/rules (UPSTREAM_CFLAGS, UPSTREAM_FFLAGS) with what dpkg-buildflags
# gives on bookworm for DEB_BUILD_MAINT_OPTIONS=hardening=+all (without -ffile-prefix-map,
# which only names the build directory). rules passes CFLAGS CPPFLAGS LDFLAGS in CFLAGS.
deb_cflags='-Wall -I/usr/include/spooles -DARCH="Linux" -DSPOOLES -DARPACK -DMATRIXSTORAGE -DUSE_MT=1 -g -O2 -fstack-protector-strong -Wformat -Werror=format-security -Wdate-time -D_FORTIFY_SOURCE=2 -Wl,-z,relro -Wl,-z,now'
deb_fflags='-fallow-argument-mismatch -g -O2 -fstack-protector-strong'
deb_ldflags='-Wl,-z,relro -Wl,-z,now'
stock_stage=1 # bump when the stock stage below changes

cache=${INTERFACIAL_CCX_CACHE:-$HOME/.cache/interfacial/ccx}
mkdir -p "$cache/src" "$outdir"
outdir=$(cd "$outdir" && pwd)
jobs=$(nproc 2>/dev/null || echo 2)

# --- build dependencies (Debian package names) ----------------------------------------------
need=(libspooles-dev libarpack2-dev liblapack-dev libblas-dev gfortran gcc make patch bzip2 xz-utils)
missing=()
for p in "${need[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' ||
    missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  if [ "$(id -u)" -eq 0 ]; then
    echo "build.sh: installing ${missing[*]}"
    # A fresh machine may have no package lists yet: update once and retry.
    apt-get install -y --no-install-recommends "${missing[@]}" >/dev/null 2>&1 || {
      apt-get update >/dev/null
      apt-get install -y --no-install-recommends "${missing[@]}" >/dev/null
    }
  else
    echo "build.sh: missing Debian packages: ${missing[*]}" >&2
    echo "          run as root: apt-get install ${missing[*]}" >&2
    exit 1
  fi
fi

sha() { sha256sum "$1" | cut -d' ' -f1; }
check_sha() { # file pin
  local got
  got=$(sha "$1")
  if [ "$got" != "$2" ]; then
    echo "build.sh: $1: SHA-256 $got, expected $2" >&2
    exit 1
  fi
}

# --- the source package -----------------------------------------------------------------------
fetch() {
  local dl=$cache/src/dl.$$
  rm -rf "$dl" && mkdir -p "$dl"
  local -a aptopt=()
  if ! grep -rqsE '^(deb-src|Types:.*deb-src)' /etc/apt/sources.list /etc/apt/sources.list.d/; then
    # A private apt configuration: the machine's deb822 entries as deb-src.
    local a=$dl/apt
    mkdir -p "$a/lists/partial" "$a/parts" "$a/cache/archives/partial"
    local f n=0
    for f in /etc/apt/sources.list.d/*.sources; do
      [ -f "$f" ] || continue
      sed 's/^Types:.*/Types: deb-src/' "$f" >"$a/parts/src$n.sources"
      n=$((n + 1))
    done
    if [ -f /etc/apt/sources.list ]; then
      sed -n 's/^deb \(.*\)/deb-src \1/p' /etc/apt/sources.list >"$a/parts/list.list"
    fi
    aptopt=(-o "Dir::Etc::sourcelist=/dev/null" -o "Dir::Etc::sourceparts=$a/parts"
      -o "Dir::State::Lists=$a/lists" -o "Dir::Cache=$a/cache")
    apt-get "${aptopt[@]}" update >"$dl/update.log" 2>&1 ||
      { cat "$dl/update.log" >&2; echo "build.sh: apt-get update (deb-src) failed" >&2; exit 1; }
  fi
  (cd "$dl" && apt-get "${aptopt[@]}" source --download-only calculix-ccx=2.20-1) \
    >"$dl/source.log" 2>&1 ||
    { cat "$dl/source.log" >&2; echo "build.sh: apt-get source calculix-ccx=2.20-1 failed" >&2; exit 1; }
  check_sha "$dl/$orig" "$orig_sha"
  check_sha "$dl/$deb" "$deb_sha"
  mv "$dl/$orig" "$dl/$deb" "$cache/src/"
  rm -rf "$dl"
}
if [ -n "$given_source" ]; then
  check_sha "$given_source" "$orig_sha"
  cp "$given_source" "$cache/src/$orig.tmp" && mv "$cache/src/$orig.tmp" "$cache/src/$orig"
fi
if [ ! -f "$cache/src/$orig" ] || [ ! -f "$cache/src/$deb" ] ||
  [ "$(sha "$cache/src/$orig")" != "$orig_sha" ] || [ "$(sha "$cache/src/$deb")" != "$deb_sha" ]; then
  echo "build.sh: fetching Debian's calculix-ccx 2.20-1 source"
  fetch
fi

# --- stock: Debian's build, objects kept --------------------------------------------------------
stock_key=$(printf '%s\n' "$orig_sha" "$deb_sha" "$deb_cflags" "$deb_fflags" "$deb_ldflags" \
  "$stock_stage" | sha256sum | cut -c1-16)
stock=$cache/stock-$stock_key
ssrc=$stock/ccx_2.20/src
if [ ! -f "$stock/.done" ]; then
  echo "build.sh: building CalculiX 2.20 with Debian's patches and flags (once; cached in $stock)"
  rm -rf "$stock" "$stock.tmp"
  mkdir -p "$stock.tmp"
  # dpkg-source's layout: the orig tarball's top directory stripped, debian/ beside it.
  tar -xjf "$cache/src/$orig" -C "$stock.tmp" --strip-components=1
  tar -xJf "$cache/src/$deb" -C "$stock.tmp"
  while read -r p; do
    case "$p" in '' | '#'*) continue ;; esac
    patch -d "$stock.tmp" -p1 --no-backup-if-mismatch -s <"$stock.tmp/debian/patches/$p"
  done <"$stock.tmp/debian/patches/series"
  mv "$stock.tmp" "$stock"
  (cd "$ssrc" && make -j"$jobs" CFLAGS="$deb_cflags" FFLAGS="$deb_fflags" \
    LDFLAGS="$deb_ldflags" >"$stock/make.log" 2>&1) ||
    { tail -30 "$stock/make.log" >&2; echo "build.sh: stock build failed ($stock/make.log)" >&2; exit 1; }
  touch "$stock/.done"
fi

# --- the library's CalculiX variant ------------------------------------------------------------
echo "build.sh: cargo build --release --features calculix"
(cd "$root" && cargo build --release --locked --lib --features calculix \
  --target-dir "$root/target/calculix" -q)
lib=$root/target/calculix/release/libinterfacial.a
native_libs='-lgcc_s -lutil -lrt -lpthread -lm -ldl -lc'

# --- ours: the edited files, our routines, the link ----------------------------------------------
key=$( {
  echo "$stock_key"
  cat "$here/edit.sh" "$here/build.sh"
  for f in "$here"/edits/* "$here"/src/*; do echo "$f"; cat "$f"; done
  sha "$lib"
} | sha256sum | cut -c1-16)
bdir=$cache/build-$key
if [ ! -x "$bdir/ccx" ]; then
  echo "build.sh: applying our edits and linking (cached in $bdir)"
  rm -rf "$bdir" "$bdir.tmp"
  mkdir -p "$bdir.tmp/src"
  files=$(grep -v '^#' "$here/edits/list" | cut -d'|' -f1 | sort -u)
  for f in $files; do cp "$ssrc/$f" "$bdir.tmp/src/"; done
  "$here/edit.sh" "$here/edits" "$bdir.tmp/src"
  objs=()
  for f in $files; do
    (cd "$bdir.tmp/src" && gfortran $deb_fflags -I"$ssrc" -c "$f") ||
      { echo "build.sh: compiling the edited $f failed" >&2; exit 1; }
    objs+=("${f%.f}.o")
  done
  for f in "$here"/src/*.f90; do
    (cd "$bdir.tmp/src" && gfortran $deb_fflags -fopenmp -c "$f") ||
      { echo "build.sh: compiling $f failed" >&2; exit 1; }
    b=$(basename "$f")
    objs+=("${b%.f90}.o")
  done
  # CalculiX's archive without its gapcon.o, with the edited objects and ours.
  cp "$ssrc/ccx_2.20.a" "$bdir.tmp/ccx_2.20.a"
  ar d "$bdir.tmp/ccx_2.20.a" gapcon.o
  if ar t "$bdir.tmp/ccx_2.20.a" | grep -qx gapcon.o; then
    echo "build.sh: gapcon.o still in ccx_2.20.a" >&2
    exit 1
  fi
  (cd "$bdir.tmp/src" && ar r ../ccx_2.20.a "${objs[@]}" 2>/dev/null)
  # Debian's link line (its Makefile after the patches) plus the library.
  (cd "$bdir.tmp" && gfortran -Wall -O2 -o ccx "$ssrc/ccx_2.20.o" ccx_2.20.a "$lib" \
    -lspooles -lpthread -larpack -llapack -lblas -lm -lc -fopenmp $deb_ldflags $native_libs \
    -Wl,-y,gapcon_ -Wl,-y,fric_ >link.log 2>&1) ||
    { cat "$bdir.tmp/link.log" >&2; echo "build.sh: link failed" >&2; exit 1; }
  for s in gapcon_ fric_; do
    grep -q "libinterfacial.a(.*): definition of $s" "$bdir.tmp/link.log" ||
      { cat "$bdir.tmp/link.log" >&2; echo "build.sh: $s does not come from the library" >&2; exit 1; }
  done
  mv "$bdir.tmp" "$bdir"
  # Keep the three newest builds.
  ls -dt "$cache"/build-* 2>/dev/null | tail -n +4 | xargs -r rm -rf
fi
cp "$bdir/ccx" "$outdir/ccx.tmp" && mv "$outdir/ccx.tmp" "$outdir/ccx"
echo "build.sh: $outdir/ccx ready in $(($(date +%s) - t_start)) s"
