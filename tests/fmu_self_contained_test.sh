#!/usr/bin/env bash
# PeriStep.fmu is self-contained: unpacked into a root that holds only glibc, the C++ runtime and the
# loader (no SuiteSparse, METIS, OpenBLAS, libgomp, libgfortran), its PeriStep.so
#   - lists no dependency outside the archive but the C/C++ runtime and glibc, and none "not found"
#     (the loader's --list, which is what ldd runs), inside that root and on this system alike;
#   - is opened, instantiated and stepped through the FMI 3.0 C ABI by examples/c/embed.c there,
# while the bare PeriStep.so of the build, in the same root, fails to load (so the root really hides
# the system's libraries). Every bundled library is needed and named in documentation/licenses, and
# none needs a glibc newer than 2.35 or a libstdc++ newer than GCC 11's.
#
#   fmu_self_contained_test.sh <cmake> <PeriStep.fmu> <embed program> <built PeriStep.so>
set -euo pipefail

if (($# != 4)); then
  echo "usage: $0 <cmake> <PeriStep.fmu> <embed program> <built PeriStep.so>" >&2
  exit 2
fi
cmake=$1 fmu=$(realpath "$2") embed=$3 bare=$4

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

# What may stay outside the archive: glibc (with its loader and the vDSO) and the C++ runtime; written
# out here rather than taken from modelDescription/bundle_libraries.sh, so that this checks the script.
runtime='^(linux-vdso\.so\.1|ld-linux-x86-64\.so\.2|libc\.so\.6|libm\.so\.6|libdl\.so\.2|libpthread\.so\.0|librt\.so\.1|libstdc\+\+\.so\.6|libgcc_s\.so\.1)$'
loader=/lib64/ld-linux-x86-64.so.2
binaries=fmu/binaries/x86_64-linux  # relative to the root

work=$(mktemp -d "${TMPDIR:-/tmp}/peristep-self-contained-XXXXXX")
trap 'rm -rf "$work"' EXIT
root=$work/root
mkdir -p "$root/fmu" "$root/bin" "$root/control"
(cd "$root/fmu" && "$cmake" -E tar xf "$fmu")
[ -f "$root/$binaries/PeriStep.so" ] || fail "no $binaries/PeriStep.so in $fmu"
cp "$embed" "$root/bin/embed"
cp "$bare" "$root/control/PeriStep.so"

# The root's runtime: the system's copies of exactly the allowed libraries that the embed program and
# PeriStep.so resolve to here, at the same paths.
while read -r soname arrow path _; do
  [ "$arrow" = "=>" ] && [[ $soname =~ $runtime ]] || continue
  mkdir -p "$root$(dirname "$path")"
  cp -L "$path" "$root$path"
done < <(env -u LD_LIBRARY_PATH ldd "$embed" "$root/$binaries/PeriStep.so" | grep -v ':$')
mkdir -p "$root$(dirname "$loader")"
cp -L "$loader" "$root$loader"

# Enter the root: chroot as root, else in a user namespace; never pass without having entered it.
# The probe runs embed without arguments, which prints its usage and exits with 2.
can_enter() {
  local status=0
  env -i "$@" /bin/embed >/dev/null 2>&1 || status=$?
  [ "$status" -eq 2 ]
}
chroot=$(command -v chroot) || fail "no chroot program (coreutils)"
enter=("$chroot" "$root")
if ! can_enter "${enter[@]}"; then
  unshare=$(command -v unshare) || fail "cannot chroot (not root?) and no unshare program to get a user namespace"
  enter=("$unshare" -r "$chroot" "$root")
  can_enter "${enter[@]}" ||
    fail "cannot enter a chroot (not root, and 'unshare -r' is refused here): the self-contained check needs one"
fi
echo "entering the root with: ${enter[*]}"
in_root() { env -i "${enter[@]}" "$@"; }  # no LD_LIBRARY_PATH or other variable from outside

# ldd's listing, checked: each dependency inside the archive's binaries folder or allowed to be outside.
check_listing() {  # <listing> <binaries folder as the listing names it> <where>
  local listing=$1 folder=$2 where=$3 soname arrow path
  echo "$listing"
  ! grep -q 'not found' <<<"$listing" || fail "$where: a dependency of PeriStep.so is not found"
  while read -r soname arrow path _; do
    [ "$arrow" = "=>" ] || continue
    [[ $path == "$folder"/* ]] || [[ $soname =~ $runtime ]] ||
      fail "$where: $soname resolves to $path, outside the FMU"
  done <<<"$listing"
}
inside=$(in_root "$loader" --list "/$binaries/PeriStep.so" 2>&1) || fail "in the root, a dependency of PeriStep.so is missing: $inside"
check_listing "$inside" "/$binaries" "in the root"
# On this system, which has every library installed, the archive's copies still come first.
check_listing "$(env -u LD_LIBRARY_PATH ldd "$root/$binaries/PeriStep.so")" "$root/$binaries" "on this system"

# Nothing shipped that PeriStep.so does not load, and each shipped library's licence named.
licenses=$root/fmu/documentation/licenses
[ -f "$licenses/license.txt" ] || fail "no documentation/licenses/license.txt in $fmu"
for file in "$root/$binaries"/*; do
  name=$(basename "$file")
  [ "$name" = PeriStep.so ] && continue
  grep -q "/$binaries/$name " <<<"$inside" || fail "$name is in the FMU but PeriStep.so does not load it"
  package=$(awk -v n="$name" '$1 == n { print $2 }' "$licenses/license.txt")
  [ -n "$package" ] || fail "$name is not listed in documentation/licenses/license.txt"
  [ -s "$licenses/$package.txt" ] || fail "no copyright file $package.txt for $name"
done

# What the binaries need of the system (the README states it): glibc >= 2.35, libstdc++ of GCC >= 11.
newest() {  # <symbol version prefix>: the highest such version any shipped binary refers to
  objdump -T "$root/$binaries"/* | grep -o "($1[0-9.]*)" | tr -d '()' | sort -V | tail -n1
}
glibc=$(newest GLIBC_) glibcxx=$(newest GLIBCXX_)
echo "newest symbol versions needed: $glibc, $glibcxx"
[ "$(printf '%s\n' "$glibc" GLIBC_2.35 | sort -V | tail -n1)" = GLIBC_2.35 ] || fail "needs $glibc > GLIBC_2.35"
[ "$(printf '%s\n' "$glibcxx" GLIBCXX_3.4.29 | sort -V | tail -n1)" = GLIBCXX_3.4.29 ] ||
  fail "needs $glibcxx > GLIBCXX_3.4.29 (GCC 11)"

# The control: without the archive's libraries beside it, PeriStep.so cannot be loaded in the root.
if control=$(in_root /bin/embed /control/PeriStep.so 2>&1); then
  fail "the bare PeriStep.so loaded in the root: the root does not hide the system's libraries"
fi
grep -q 'cannot open shared object file' <<<"$control" || fail "the control failed for another reason: $control"
echo "control (bare PeriStep.so in the root): $control"

# The FMU's own PeriStep.so: loaded, instantiated, initialized and stepped through the C ABI.
output=$(in_root /bin/embed "/$binaries/PeriStep.so" 2>&1) || fail "embed on the FMU's PeriStep.so in the root: $output"
echo "$output"
grep -Eq 'errorL2 = [0-9]' <<<"$output" || fail "embed printed no errorL2"
echo "PASS: PeriStep.fmu loads and steps with only glibc and the C++ runtime outside it"
