#include "uuvplan/text/trial_notes_text.h"

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "uuvplan/model/dof.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::text {

using ident::TrialNote;
using ident::TrialNoteKind;
using model::Significant;

namespace {

// "pitch (travel 12°, 0.42 rad/s rms)" of `name` from its travel and velocity rms (NaN: not
// logged); `name` alone when neither was.
std::string MotionOf(const std::string& name, double travel, double rms) {
  const std::optional<model::Dof> dof = model::ParseDof(name);
  const bool rotation = dof && model::IsRotational(*dof);
  std::vector<std::string> parts;
  if (std::isfinite(travel)) {
    parts.push_back("travel " +
                    (rotation ? model::AngleText(travel) : Significant(travel, 3) + " m"));
  }
  if (std::isfinite(rms)) {
    parts.push_back(Significant(rms, 3) + (rotation ? " rad/s" : " m/s") + " rms");
  }
  return parts.empty() ? name : name + " (" + model::Join(parts) + ")";
}

}  // namespace

std::string OtherMotionText(const std::vector<TrialNote>& notes) {
  std::vector<std::string> motions;
  const TrialNote* any = nullptr;
  for (const TrialNote& n : notes) {
    if (n.kind != TrialNoteKind::kOtherDofMotion) continue;
    motions.push_back(MotionOf(n.names[0], n.numbers[0], n.numbers[1]));
    any = &n;
  }
  if (any == nullptr) return "";
  return "motion in other DOFs: " + model::Join(motions) + ", beside " +
         MotionOf(any->names[1], any->numbers[2], any->numbers[3]) +
         " itself; the one-DOF model holds none of it (a coupling: `uuvplan diagnose` tests it)";
}

std::string NoteText(const TrialNote& n) {
  const auto count = [&n](std::size_t i) {
    return std::to_string(static_cast<long>(n.numbers[i]));
  };
  switch (n.kind) {
    case TrialNoteKind::kHeadingUnwrapped:
      return "heading unwrapped (" + count(0) + " jumps of 2π)";
    case TrialNoteKind::kOutliersExcluded:
      return count(0) + " " + n.names[0] +
             " outlier(s) excluded (first at t = " + Significant(n.numbers[1], 4) +
             " s, residual " + Significant(n.numbers[2], 4) + ")";
    case TrialNoteKind::kNoiseAboveDeclared:
      return n.names[0] + " noise estimated from the data (" + Significant(n.numbers[0], 4) +
             ") is more than 3× the declared sensor sigma (" + Significant(n.numbers[1], 4) + ")";
    case TrialNoteKind::kUnusableColumn:
      return "column " + n.names[0] + " has fewer than 3 values (all NaN?): not used";
    case TrialNoteKind::kGaps:
      return count(0) + " gap(s) in the " + n.names[0] + " samples (longest " +
             Significant(n.numbers[1], 4) + " s); filters do not cross them";
    case TrialNoteKind::kBeforeFirstForce:
      return "the first " + Significant(n.numbers[0], 4) +
             " s of the log precede its first force row (t = " + Significant(n.numbers[1], 4) +
             " s): their measurements are not used (the force there was not logged)";
    case TrialNoteKind::kLog:
      return n.names[0];
    case TrialNoteKind::kOtherDofMotion:
      return OtherMotionText({n});
  }
  return std::string(ident::kTrialNoteKindNames.Name(n.kind));
}

std::vector<std::string> NoteTexts(const std::vector<TrialNote>& notes) {
  std::vector<std::string> texts;
  for (const TrialNote& n : notes) texts.push_back(NoteText(n));
  return texts;
}

}  // namespace uuvplan::text
