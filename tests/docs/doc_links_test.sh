#!/bin/sh
# Every Markdown link to a local file in the documentation must point to a file that exists:
# README.md keeps the current state and links to docs/ for the detail, so a moved or renamed
# document must not leave a link behind. Checks README.md, docs/*.md and compare/README.md;
# web links (scheme://, mailto:) and links to an anchor of the same file are not files and are
# skipped; a link's own anchor (#...) is dropped before the check. Paths are relative to the
# file that holds the link, as a Markdown viewer reads them.
#
# usage: tests/docs/doc_links_test.sh SOURCE_DIR
set -eu
root="${1:?usage: doc_links_test.sh SOURCE_DIR}"
cd "$root"
bad=0
checked=0
for doc in README.md docs/*.md compare/README.md; do
  [ -f "$doc" ] || continue
  dir=$(dirname "$doc")
  # Inline links and images: ](target) or ](target "title"); code spans are not links, but a
  # "](" inside one is rare enough that the check reads every line.
  set -f  # a target such as docs/*.md is a name to check, not a pattern to expand
  for target in $(grep -o ']([^)[:space:]]*' "$doc" | sed 's/^](//'); do
    case "$target" in
      *://* | mailto:* | '#'* | '') continue ;;
    esac
    path="${target%%#*}"
    checked=$((checked + 1))
    if [ ! -e "$dir/$path" ]; then
      echo "$doc: broken link to $target (no file $dir/$path)"
      bad=$((bad + 1))
    fi
  done
  set +f
done
echo "$checked local links checked, $bad broken"
[ "$checked" -gt 0 ] || { echo "no local link found: the check read nothing"; exit 1; }
[ "$bad" -eq 0 ]
