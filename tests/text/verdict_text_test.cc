// The pool verdict in words (text/verdict_text.h), from verdicts made by hand: the sentence
// for each hostability, a DOF's reason in the order the verdict found it (the planner's
// message, a given plan's failing trials, what a larger pool does not lift), and a loop's end
// read against the verdict.
#include "uuvplan/text/verdict_text.h"

#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "uuvplan/model/util/text.h"

namespace uuvplan::text {
namespace {

using model::Dof;
using planner::DofVerdict;
using planner::Hostability;
using planner::PoolVerdict;

const model::Pool kPool{"tank", 10.0, 6.0, 4.0, 1.0};

DofVerdict Dof1(Dof dof, Hostability h) {
  DofVerdict d;
  d.dof = dof;
  d.hosted = h == Hostability::kAll;
  d.hostability = h;
  return d;
}

TEST(VerdictText, TheSentenceSaysHowMuchOfTheBoxThePoolHosts) {
  PoolVerdict v;
  v.goal.target_percent = 5.0;
  v.hosted = true;
  v.hostability = Hostability::kAll;
  v.dofs = {Dof1(Dof::kSurge, Hostability::kAll), Dof1(Dof::kYaw, Hostability::kAll)};
  EXPECT_EQ(VerdictSentence(v, kPool),
            "Pool tank CAN host the identification of surge, yaw to 5% (every parameter of "
            "interest's 100·σ/|θ|)");
  v.hosted = false;
  v.hostability = Hostability::kPart;
  v.dofs[1] = Dof1(Dof::kYaw, Hostability::kPart);
  EXPECT_NE(VerdictSentence(v, kPool).find("can host the identification of yaw to 5% (every "
                                           "parameter of interest's 100·σ/|θ|) for PART of the "
                                           "a priori box only"),
            std::string::npos);
  EXPECT_EQ(VerdictAnswer(Hostability::kNone), "CANNOT host it");
  // A vehicle file with an identified model is planned about its estimates: the box named is
  // that one, in the sentence, the DOF's line, the assumption and the short answer.
  v.identified_box = true;
  EXPECT_NE(VerdictSentence(v, kPool).find("for PART of the box about the identified model only"),
            std::string::npos);
  for (const auto& line : VerdictLines(v, kPool)) {
    EXPECT_EQ(line.find("a priori box"), std::string::npos) << line;
  }
  EXPECT_EQ(VerdictAnswer(Hostability::kPart, true),
            "can host it for PART of the box about the identified model only");
  // A payload on an identified base: the box is the base's estimates with the payload's rules,
  // not an identified model of this vehicle.
  v.derived_box = true;
  EXPECT_NE(VerdictSentence(v, kPool).find(
                "for PART of the box about the base's estimates with the payload only"),
            std::string::npos);
  for (const auto& line : VerdictLines(v, kPool)) {
    EXPECT_EQ(line.find("identified model"), std::string::npos) << line;
  }
  EXPECT_EQ(VerdictAnswer(Hostability::kPart, true, true),
            "can host it for PART of the box about the base's estimates with the payload only");
  v.derived_box = false;
  PoolVerdict nothing;
  nothing.unplanned = "no DOF can be planned";
  EXPECT_NE(VerdictSentence(nothing, kPool).find("CANNOT host the identification of  to"),
            std::string::npos);
  EXPECT_NE(VerdictSentence(nothing, kPool).find(": no DOF can be planned"), std::string::npos);
}

TEST(VerdictText, ADofsReasonInTheOrderTheVerdictFoundIt) {
  PoolVerdict v;
  DofVerdict d = Dof1(Dof::kSurge, Hostability::kNone);
  d.message = "surge: the drag is not to the target 5%.";
  d.unlifted = true;
  d.unlifted_travel = 12.0;
  planner::TrialPoolCheck fails{"surge_steady_1", Dof::kSurge, {}};
  fails.check.feasible = false;
  fails.check.reasons = {"thruster A reverses", "duration 300 s exceeds the 240 s limit"};
  planner::TrialPoolCheck fits{"surge_sine", Dof::kSurge, {}};
  v.plan_checks = {fails, fits};
  EXPECT_EQ(DofReason(v, d, kPool),
            "surge: the drag is not to the target 5%. plan trial 'surge_steady_1': thruster A "
            "reverses; duration 300 s exceeds the 240 s limit A pool offering 12 m of free "
            "length (14 m wall to wall) does not lift it either: the trials never reverse a "
            "thruster, so the drag is seen over one speed range per direction.");
  EXPECT_EQ(DofReason(v, Dof1(Dof::kYaw, Hostability::kAll), kPool), "");
}

TEST(VerdictText, TheLinesStartWithTheSentenceAndNameThePool) {
  PoolVerdict v;
  v.hosted = true;
  v.hostability = Hostability::kAll;
  DofVerdict d = Dof1(Dof::kSurge, Hostability::kAll);
  d.extent = 7.5;
  v.dofs = {d};
  const auto lines = VerdictLines(v, kPool);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0], VerdictSentence(v, kPool));
  EXPECT_EQ(lines[1],
            "  pool: 10 x 6 x 4 m wall to wall, margin 1 m: free 8 x 4 x 2 m; tether 3 "
            "turns");
  EXPECT_EQ(lines[2],
            "  surge: hosted; its trials span 7.5 of the 8 m of free length (10 m wall "
            "to wall)");
}

TEST(VerdictText, ALoopOutsideTheHostablePartSaysSoBeforeItsOwnMessage) {
  PoolVerdict v;
  v.hostability = Hostability::kPart;
  v.dofs = {Dof1(Dof::kHeave, Hostability::kPart)};
  planner::LoopResult r;
  r.message = "stuck: heave kq";
  EXPECT_EQ(LoopEndMessage(r, v, kPool), "stuck: heave kq");
  r.outside_part = {Dof::kHeave};
  const std::string m = LoopEndMessage(r, v, kPool);
  EXPECT_EQ(m.rfind("the first trials place heave outside the part of the a priori box the pool "
                    "hosts (the verdict before any trial: Pool tank can host",
                    0),
            0u)
      << m;
  EXPECT_TRUE(model::EndsWith(m, "); stuck: heave kq")) << m;
}

}  // namespace
}  // namespace uuvplan::text
