#!/usr/bin/env bash
# No output of any command holds a value that was never computed or a unit never filled in:
# no "nan" or "inf" (a number that could not be computed is said to be so, and JSON writes null),
# no "a·b" or "?" standing for a unit. Runs every command on every case, and on the real
# campaigns when ../shared is present (scripts/every_output.sh), then reads what each printed and
# wrote: text, JSON, YAML, CSV, Markdown, and the HTML and SVG of the report without their
# embedded images. Lists every offending line; exit 1 when there is one. ctest runs it as
# Outputs.NoPlaceholders.
#
# Usage: scripts/no_placeholders.sh PROGRAM [DIR]   (DIR: keep the outputs there)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
[ $# -ge 1 ] || { echo "usage: $0 PROGRAM [DIR]" >&2; exit 2; }
out="${2:-}"
if [ -z "$out" ]; then
  out=$(mktemp -d)
  trap 'rm -rf "$out"' EXIT
fi
"$root/scripts/every_output.sh" "$1" "$out"
[ -d "$root/../shared/data" ] ||
  echo "no_placeholders: ../shared absent: the real campaigns are not read"

# A word "nan"/"inf" (any case, signed), an "a·b" unit, or "?" where a unit goes.
pattern='(^|[^[:alnum:]_])[-+]?(nan|inf)([^[:alnum:]_]|$)|a·b|\(\?\)|[0-9] \?([ ,;)]|$)'
found=$(cd "$out" && find . -type f \( -name '*.stdout' -o -name '*.stderr' -o -name '*.json' \
  -o -name '*.yaml' -o -name '*.csv' -o -name '*.md' -o -name '*.html' -o -name '*.svg' \) |
  sort | while read -r f; do
    # data: URIs (the report's embedded images) are base64, where any letters may meet.
    sed -E 's#data:[a-z/+]+;base64,[A-Za-z0-9+/=]+#data:…#g' "$f" |
      grep -n -i -E "$pattern" | sed "s#^#${f#./}:#" || true
  done)
count=$(cd "$out" && find . -type f | wc -l)
if [ -n "$found" ]; then
  echo "outputs holding a placeholder or an uncomputed number (of $count files):"
  echo "$found" | cut -c1-300
  exit 1
fi
echo "no_placeholders: none in $count output files"
