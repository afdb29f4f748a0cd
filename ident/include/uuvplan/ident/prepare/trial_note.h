// What preparing a trial did to its data (unwrapped, excluded, not used), as data: the kind of
// remark and the values it quotes. The text layer words it (text/trial_notes_text.h).
#pragma once

#include <string>
#include <vector>

#include "uuvplan/model/util/enum_names.h"

namespace uuvplan::ident {

/// What a TrialNote says; the comment lists what it quotes, in `names` then `numbers` order.
enum class TrialNoteKind {
  /// numbers {jumps of 2π}: the heading was unwrapped.
  kHeadingUnwrapped,
  /// names {signal: "position" or "velocity"}, numbers {count, first time in s, its residual}.
  kOutliersExcluded,
  /// names {signal}, numbers {σ estimated from the data, σ declared}: more than 3× declared.
  kNoiseAboveDeclared,
  /// names {column}: fewer than 3 values, not used.
  kUnusableColumn,
  /// names {signal}, numbers {gaps, longest gap in s}: filters do not cross them.
  kGaps,
  /// numbers {duration in s, time of the first force row in s}: measurements before the
  /// first force row are not used.
  kBeforeFirstForce,
  /// names {the log's note (model::TrialLog::notes)}: what reading the log did.
  kLog,
  /// names {another DOF, the trial's DOF}, numbers {travel of the other's position in m or rad,
  /// rms of its velocity in m/s or rad/s, the same two of the trial's DOF; NaN: not logged}:
  /// the vehicle moved in that DOF too (other_motion.h).
  kOtherDofMotion,
};

inline constexpr model::EnumNames<TrialNoteKind, 8> kTrialNoteKindNames{{{
    {TrialNoteKind::kHeadingUnwrapped, "heading_unwrapped"},
    {TrialNoteKind::kOutliersExcluded, "outliers_excluded"},
    {TrialNoteKind::kNoiseAboveDeclared, "noise_above_declared"},
    {TrialNoteKind::kUnusableColumn, "unusable_column"},
    {TrialNoteKind::kGaps, "gaps"},
    {TrialNoteKind::kBeforeFirstForce, "before_first_force"},
    {TrialNoteKind::kLog, "log"},
    {TrialNoteKind::kOtherDofMotion, "other_dof_motion"},
}}};

struct TrialNote {
  TrialNoteKind kind = TrialNoteKind::kLog;
  std::vector<std::string> names;  ///< names in the order of the kind's list
  std::vector<double> numbers;     ///< numbers in the order of the kind's list
};

}  // namespace uuvplan::ident
