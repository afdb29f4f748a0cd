#!/usr/bin/env bash
# The libraries below the text layer report remarks on a result as data (a kind and the values
# it quotes) and the text layer words them (docs/architecture.md, Conventions): no statement in
# model/, ident/ or planner/ pushes a string literal into `notes`, `warnings` or `reasons`.
# Files still to convert are listed in `pending` below; a listed file that no longer has such a
# statement is reported so that the list only shrinks. Lists every offending statement and
# exits 1 when there is one; checked by ctest as Structure.NoSentencesInLibraries.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
pending=(
  ident/src/estimators/integral_inertia.cc
  ident/src/estimators/joint_ls.cc
  ident/src/estimators/output_error.cc
  ident/src/estimators/steady_state.cc
  ident/src/identify.cc
  ident/src/identify_estimate.cc
  ident/src/identify_prepare.cc
  ident/src/identify_refine.cc
  ident/src/identify_validate.cc
  ident/src/identify_written_model.cc
  ident/src/stats/monte_carlo.cc
  model/src/trial_log.cc
  planner/src/design/combined_design.cc
  planner/src/design/dof_planning_problem.cc
  planner/src/design/paper_procedure.cc
  planner/src/design/parameter_box.cc
  planner/src/design/sine_design.cc
  planner/src/design/steady_design.cc
  planner/src/design/switched_design.cc
  planner/src/design/thrust_limits.cc
  planner/src/determinacy.cc
  planner/src/loop/design_loop.cc
  planner/src/loop/next_trial_policy.cc
  planner/src/pool/pool_check.cc
  planner/src/schedule_planner.cc
)
# One line "file:line: statement" per push of a statement holding a string literal.
sentences() {
  find model ident planner -name '*.cc' -o -name '*.h' | sort | while read -r f; do
    perl -0ne 'while (/((?:notes|warnings|reasons)(?:\.|->)(?:push_back|emplace_back)\([^;]*?"[^;]*?;)/g) {
      my $line = 1 + (substr($_, 0, $-[0]) =~ tr/\n//);
      (my $s = $1) =~ s/\s+/ /g;
      print "$ARGV:$line: $s\n";
    }' "$f"
  done
}
found=$(sentences)
status=0
new=$(printf '%s\n' "$found" | grep -v -F -f <(printf '%s:\n' "${pending[@]}" | sed '/^:$/d') || true)
if [ -n "${new//[$'\n']/}" ]; then
  echo "sentences pushed into notes/warnings/reasons in model/, ident/ or planner/ (report a"
  echo "kind and its values; text/ words it):"
  echo "$new"
  status=1
fi
for f in "${pending[@]}"; do
  if ! printf '%s\n' "$found" | grep -q -F "$f:"; then
    echo "$f has no sentence left: remove it from the pending list in $0"
    status=1
  fi
done
[ "$status" -eq 0 ] && echo "no sentences pushed into notes/warnings/reasons in the libraries"
exit "$status"
