#!/usr/bin/env bash
# The libraries' READMEs quote their examples: every ```cpp block of each libs/<lib>/README.md
# must be lines of the file the README first links under apps/ (compared without leading
# spaces, in order; a `// ...` line stands for lines left out), so the quoted code is code that
# compiles and runs as a test.
#   readme_snippets.sh <source root>
set -euo pipefail
root="$1"
status=0
count=0
for readme in "$root"/libs/*/README.md; do
  count=$((count + 1))
  example=$(grep -o '](\.\./\.\./apps/[^)]*)' "$readme" | head -1 | sed 's/^](\.\.\/\.\.\///; s/)$//')
  if [ -z "$example" ] || [ ! -f "$root/$example" ]; then
    echo "$readme: links no example under apps/ (or it does not exist: '$example')" >&2
    status=1
    continue
  fi
  # awk: the example's lines (stripped) in an array; each quoted line must be found at or
  # after the line where the previous one was found.
  awk -v readme="$readme" -v example="$example" '
    function strip(s) { sub(/^[ \t]+/, "", s); sub(/[ \t\r]+$/, "", s); return s }
    FNR == NR { lines[++n] = strip($0); next }
    /^```cpp/ { inBlock = 1; at = 1; next }
    /^```/ { inBlock = 0; next }
    inBlock {
      q = strip($0)
      if (q == "" || q == "// ...") next
      for (i = at; i <= n && lines[i] != q; ++i) {}
      if (i > n) { printf "%s: not a line of %s (after the previous one): %s\n", readme, example, q > "/dev/stderr"; bad = 1 }
      else at = i + 1
    }
    END { exit bad }' "$root/$example" "$readme" || status=1
done
if [ "$count" = 0 ]; then
  echo "readme_snippets.sh: no libs/*/README.md under $root" >&2
  exit 1
fi
[ "$status" = 0 ] && echo "$count library READMEs quote their examples line for line"
exit "$status"
