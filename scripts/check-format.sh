#!/usr/bin/env bash
# Every C++ file of e2d follows .clang-format, as clang-format 14 (Debian 12's) lays it out.
# Prints each file that does not, with its first differing lines, and exits 1; exits 0 when all
# follow. To fix: `clang-format -i <file>` (or scripts/check-format.sh --fix for every file).
# Code that must keep a hand layout (a table, a macro list) sits between `// clang-format off`
# and `// clang-format on`.
set -uo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
if ! command -v clang-format >/dev/null; then
  echo "check-format: clang-format is not installed (Debian package clang-format)" >&2
  exit 1
fi
version=$(clang-format --version | sed -E 's/.*version ([0-9]+).*/\1/')
if [ "$version" != 14 ]; then
  # Other versions lay out some constructs differently; the tree follows 14's layout.
  echo "check-format: clang-format $version found; the layout is clang-format 14's, not checked"
  exit 0
fi
mapfile -t files < <(git ls-files '*.cpp' '*.hpp' '*.h' '*.inl')
if [ "${1:-}" = --fix ]; then
  printf '%s\0' "${files[@]}" | xargs -0 -P2 -n 25 clang-format -i
  exit 0
fi
bad=0
for f in "${files[@]}"; do
  if ! out=$(clang-format "$f" | diff -u "$f" -); then
    bad=$((bad + 1))
    [ "$bad" -le 10 ] && { echo "$f does not follow .clang-format:"; head -12 <<<"$out" | tail -n +3; }
  fi
done
if [ "$bad" -gt 0 ]; then
  echo "check-format: $bad of ${#files[@]} files do not follow .clang-format (fix: clang-format -i <file>)"
  exit 1
fi
echo "check-format: all ${#files[@]} C++ files follow .clang-format"
