#!/usr/bin/env bash
# Collects what PeriStep.so needs beyond glibc and the C++ runtime, so that the FMU loads on a machine
# without Debian 12's SuiteSparse, METIS, OpenBLAS, libgomp and libgfortran:
#   <out>/binaries/x86_64-linux/<soname>   every such shared library of the dependency closure, run
#                                          path set to $ORIGIN so that each finds its own dependencies
#                                          beside it (RUNPATH applies only to an object's direct needs)
#   <out>/documentation/licenses/          the Debian copyright file of each package shipped, and
#                                          license.txt (FMI 3.0 Sec. 2.5: the licences' entry point)
# Debian ships these libraries only as shared objects or as non-PIC archives, which cannot go into a
# shared object; SUNDIALS is linked statically instead, its copyright listed with --static.
#
#   [PATCHELF=<path>] bundle_libraries.sh <PeriStep.so> <out> [--static <package>...]
set -euo pipefail

if (($# < 2)); then
  echo "usage: $0 <PeriStep.so> <out> [--static <package>...]" >&2
  exit 2
fi
library=$1 out=$2
shift 2
static_packages=()
if (($#)); then
  [ "$1" = --static ] || { echo "bundle_libraries: expected --static, got $1" >&2; exit 2; }
  shift
  static_packages=("$@")
fi

# The C/C++ runtime and glibc: present on every Linux importer, so they stay external.
runtime='^(linux-vdso\.so\.1|ld-linux-x86-64\.so\.2|libc\.so\.6|libm\.so\.6|libdl\.so\.2|libpthread\.so\.0|librt\.so\.1|libstdc\+\+\.so\.6|libgcc_s\.so\.1)$'

binaries=$out/binaries/x86_64-linux
licenses=$out/documentation/licenses
rm -rf "$out"
mkdir -p "$binaries" "$licenses"

owner() {  # the Debian package that installed a file (under /lib or /usr/lib: Debian 12 merges the two)
  local package candidate
  for candidate in "$1" "${1#/usr}" "/usr$1"; do
    if package=$(dpkg-query -S "$candidate" 2>/dev/null | head -n1) && [ -n "$package" ]; then
      echo "${package%%:*}"
      return
    fi
  done
  echo "bundle_libraries: no package owns $1" >&2
  exit 1
}

copyright() {  # copies a package's copyright file once; fails if the system was stripped of it
  local file=/usr/share/doc/$1/copyright
  [ -r "$file" ] || { echo "bundle_libraries: $file is missing: cannot ship $1 without its licence" >&2; exit 1; }
  cp -L "$file" "$licenses/$1.txt"
}

index=$licenses/license.txt.tmp
{
  echo "PeriStep.fmu: licences of the third-party code it contains."
  echo "Each file <package>.txt here is the Debian 12 copyright file of that package; the corresponding"
  echo "source is that package's Debian source at the version named (apt-get source <package>=<version>,"
  echo "or snapshot.debian.org)."
  echo
  echo "Shared libraries in binaries/x86_64-linux (loaded by PeriStep.so through its run path \$ORIGIN):"
} >"$index"

# ldd lists the whole dependency closure, one "soname => path (address)" per line.
ldd_output=$(env -u LD_LIBRARY_PATH ldd "$library")
if grep -q 'not found' <<<"$ldd_output"; then
  echo "bundle_libraries: unresolved dependencies of $library:" >&2
  grep 'not found' <<<"$ldd_output" >&2
  exit 1
fi
declare -A shipped=()
while read -r soname arrow path _; do
  [ "$arrow" = "=>" ] || continue
  [[ $soname =~ $runtime ]] && continue
  real=$(readlink -f "$path")
  package=$(owner "$real")
  cp -L "$real" "$binaries/$soname"
  chmod 644 "$binaries/$soname"
  "${PATCHELF:-patchelf}" --set-rpath '$ORIGIN' "$binaries/$soname"
  [ -n "${shipped[$package]:-}" ] || copyright "$package"
  shipped[$package]=1
  printf '  %-28s %s %s (%s.txt)\n' "$soname" "$package" "$(dpkg-query -W -f='${Version}' "$package")" \
    "$package" >>"$index"
done <<<"$ldd_output"

if ((${#static_packages[@]})); then
  echo >>"$index"
  echo "Linked statically into PeriStep.so:" >>"$index"
  for package in "${static_packages[@]}"; do
    copyright "$package"
    printf '  %-28s %s (%s.txt)\n' "$package" "$(dpkg-query -W -f='${Version}' "$package")" "$package" >>"$index"
  done
fi
# Written last and renamed: the build's marker that the bundle is complete.
mv "$index" "$licenses/license.txt"
