#!/usr/bin/env bash
# Lists the functions longer than N lines (default 80) in the C++ sources outside tests/ and
# bench/, longest first, and exits 1 when there is one (docs/architecture.md, Conventions).
# Needs universal-ctags (scripts/install-deps.sh); exits 77 (ctest: skipped) without it.
set -euo pipefail
N="${1:-80}"
cd "$(dirname "${BASH_SOURCE[0]}")/.."
if ! command -v ctags >/dev/null; then
  echo "function_lengths: universal-ctags is not installed (scripts/install-deps.sh)" >&2
  exit 77
fi
long=$(ctags --c++-kinds=f --fields=+ne -f - -R --languages=C++ model ident planner text io report cli 2>/dev/null |
  awk -F'\t' -v N="$N" '{line=""; end="";
    for (i = 4; i <= NF; i++) { if ($i ~ /^line:/) line = substr($i, 6); if ($i ~ /^end:/) end = substr($i, 5) }
    if (line != "" && end != "") { n = end - line + 1; if (n > N) print n, $2 ":" line, $1 } }' | sort -rn)
if [ -n "$long" ]; then
  echo "functions over $N lines:"
  echo "$long"
  exit 1
fi
echo "no function over $N lines in model/, ident/, planner/, text/, io/, report/, cli/"
