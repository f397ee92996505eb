#!/usr/bin/env bash
# Applies hosts/calculix/edits/list to a CalculiX source directory. Each edit finds its place
# by a short anchor (a fixed string that must occur on exactly one line of the file, or, with a
# scope, on the first line containing it after the one line holding the scope) and inserts one
# of our snippets (edits/*.f) there. Nothing of CalculiX's is copied: the snippets are ours.
# Usage: edit.sh EDITS_DIR SRC_DIR   (edits the files of SRC_DIR in place; fails loudly)
set -euo pipefail
edits=$1
src=$2
n=0
while IFS='|' read -r file scope anchor mode snippet; do
  case "$file" in '' | '#'*) continue ;; esac
  f="$src/$file"
  [ -f "$f" ] || { echo "edit.sh: $file: no such file in $src" >&2; exit 1; }
  [ -f "$edits/$snippet" ] || { echo "edit.sh: snippet $snippet missing" >&2; exit 1; }
  awk -v scope="$scope" -v anchor="$anchor" -v mode="$mode" -v snip="$edits/$snippet" \
    -v name="$file" '
    { line[NR] = $0 }
    END {
      start = 1
      if (scope != "") {
        c = 0
        for (i = 1; i <= NR; i++) if (index(line[i], scope)) { c++; s = i }
        if (c != 1) { printf "edit.sh: %s: scope \"%s\" found %d times (want 1)\n", name, scope, c > "/dev/stderr"; exit 3 }
        a = 0
        for (i = s + 1; i <= NR && i <= s + 40; i++) if (index(line[i], anchor)) { a = i; break }
        if (a == 0) { printf "edit.sh: %s: anchor \"%s\" not within 40 lines after \"%s\"\n", name, anchor, scope > "/dev/stderr"; exit 3 }
      } else {
        c = 0
        for (i = 1; i <= NR; i++) if (index(line[i], anchor)) { c++; a = i }
        if (c != 1) { printf "edit.sh: %s: anchor \"%s\" found %d times (want 1)\n", name, anchor, c > "/dev/stderr"; exit 3 }
      }
      if (mode == "before") at = a - 1
      else if (mode == "after") at = a
      else if (mode ~ /^end(if|do)[0-9]$/) {
        word = substr(mode, 1, 5); want = substr(mode, 6) + 0; k = 0; at = 0
        for (i = a + 1; i <= NR && i <= a + 40; i++)
          if (line[i] ~ ("^[ \t]*" word "[ \t]*$")) { k++; if (k == want) { at = i; break } }
        if (at == 0) { printf "edit.sh: %s: no %s #%d within 40 lines after \"%s\"\n", name, word, want, anchor > "/dev/stderr"; exit 3 }
      } else { printf "edit.sh: unknown mode %s\n", mode > "/dev/stderr"; exit 3 }
      for (i = 1; i <= at; i++) print line[i]
      while ((getline l < snip) > 0) print l
      for (i = at + 1; i <= NR; i++) print line[i]
    }' "$f" >"$f.edit"
  mv "$f.edit" "$f"
  n=$((n + 1))
done <"$edits/list"
echo "edit.sh: $n edits applied"
