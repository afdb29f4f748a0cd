#!/usr/bin/env bash
# Needs universal-ctags. Used to keep every function outside tests/ and bench/ within 120 lines.
# Lists functions longer than N lines (default 120) in C++ sources outside tests/ and bench/.
N="${1:-120}"
ctags --c++-kinds=f --fields=+ne -f - -R --languages=C++ model ident planner 2>/dev/null |
 awk -F'\t' -v N="$N" '{line=""; end=""; for(i=4;i<=NF;i++){ if($i ~ /^line:/){line=substr($i,6)} if($i ~ /^end:/){end=substr($i,5)} } if(line!="" && end!=""){ n=end-line+1; if(n>N) print n, $2":"line, $1 } }' | sort -rn
