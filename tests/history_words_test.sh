#!/usr/bin/env bash
# The project's files describe the project as it is, not how it got there: no tracked text file may name a
# development session or tracker issue by number ("session 12", "issues 5", case-insensitive). The history
# lives in git; the decisions that measurements made are in docs/decisions/.
#
#   history_words_test.sh          (from anywhere: the repository is found from this script's location)
#
# Outside a git work tree it prints PERISTEP_SKIP and exits 0 (ctest reports it skipped), or fails when CI is set.
# Prints every offending line as path:line:text and exits 1, or prints how many text files it read and exits 0.
# Binary files (grep -I) are skipped; this script is left out, since it has to name the pattern.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(git -C "$here" rev-parse --show-toplevel 2>/dev/null) || {
  # A source tree without git (an unpacked archive) has no list of tracked files: skipped, failed in CI.
  [[ -n "${CI:-}" ]] && { echo "history words: $here is not inside a git work tree" >&2; exit 2; }
  echo "PERISTEP_SKIP: history words: $here is not inside a git work tree"
  exit 0
}
cd "$root"
self=$(realpath --relative-to="$root" "$here/$(basename "${BASH_SOURCE[0]}")")
pattern='(session|issue)s? [0-9]'

# Tracked files that exist in the work tree and hold text.
files=()
while IFS= read -r -d '' f; do
  [[ "$f" == "$self" || ! -f "$f" ]] && continue
  files+=("$f")
done < <(git ls-files -z)
# (xargs reports 123 when a batch has no match; that is not an error here.)
text=()
if ((${#files[@]})); then
  while IFS= read -r -d '' f; do text+=("$f"); done < <(printf '%s\0' "${files[@]}" | xargs -0 grep -I -l -Z -e '' -- || true)
fi

hits=
if ((${#text[@]})); then
  hits=$(printf '%s\0' "${text[@]}" | xargs -0 grep -n -i -E -H -e "$pattern" -- || true)
fi
if [[ -n "$hits" ]]; then
  printf '%s\n' "$hits"
  found=$(printf '%s\n' "$hits" | wc -l)
  echo "history words: $found found in ${#text[@]} files (pattern '$pattern', case-insensitive)" >&2
  exit 1
fi
echo "history words: 0 found in ${#text[@]} files"
