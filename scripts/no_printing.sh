#!/usr/bin/env bash
# The libraries below the text layer return data and print nothing: no std::cout, std::cerr,
# std::clog or printf-family call (printf, fprintf, snprintf, ...) in model/, ident/ or
# planner/ (docs/architecture.md, Conventions). Lists every such line and exits 1 when there
# is one; checked by ctest as Structure.NoPrintingInLibraries.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
found=$(grep -rnE 'std::(cout|cerr|clog)|printf' model ident planner || true)
if [ -n "$found" ]; then
  echo "printing in model/, ident/ or planner/ (the text layer words their results):"
  echo "$found"
  exit 1
fi
echo "no printing in model/, ident/, planner/"
