// Steady-state runs and their legs (see steady_design.h).
#include "uuvplan/planner/design/steady_design.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <sstream>

#include "options_check.h"
#include "uuvplan/model/effects.h"
#include "uuvplan/model/mapping.h"
#include "uuvplan/model/util/text.h"
#include "uuvplan/planner/design/fisher_information.h"
#include "uuvplan/planner/design/seed_rules.h"
#include "uuvplan/planner/design/thrust_limits.h"

namespace uuvplan::planner {

bool SteadyDesignOptions::IsValid(std::string* error) const {
  internal::OptionsCheck check("SteadyDesignOptions", error);
  check.Require(legs >= 0, "legs", legs, ">= 0")
      .Require(levels >= 1, "levels", levels, ">= 1")
      .Require(settle_tolerance > 0 && settle_tolerance < 1, "settle_tolerance", settle_tolerance,
               "0 < tol < 1")
      .Require(min_hold_s > 0, "min_hold_s", min_hold_s, "> 0")
      .Require(speed_rel_sigma > 0, "speed_rel_sigma", speed_rel_sigma, "> 0")
      .Require(max_legs_per_trial >= 1, "max_legs_per_trial", max_legs_per_trial, ">= 1");
  return check.ok();
}

std::vector<int> EfficientRounding(const std::vector<double>& w, int N) {
  const int C = static_cast<int>(w.size());
  std::vector<int> n(C, 0);
  if (N <= 0 || C == 0) return n;
  const double top = *std::max_element(w.begin(), w.end());
  if (!(top > 0)) return n;  // no support: nothing to apportion (all-zero or NaN weights)
  int p = 0;
  for (double x : w) p += x > 1e-3 * top ? 1 : 0;
  // n_c = ceil((N - p/2)·w_c) on the support, then the apportionment adjustments.
  const double sum = std::accumulate(w.begin(), w.end(), 0.0);
  for (int c = 0; c < C; ++c) {
    if (w[c] > 1e-3 * top) n[c] = static_cast<int>(std::ceil((N - 0.5 * p) * w[c] / sum));
  }
  int total = std::accumulate(n.begin(), n.end(), 0);
  while (total > N) {
    int best = -1;
    double best_r = -1.0;
    for (int c = 0; c < C; ++c) {
      if (n[c] == 0) continue;
      const double r = (n[c] - 1) / (w[c] / sum);
      if (r > best_r) {
        best_r = r;
        best = c;
      }
    }
    --n[best];
    --total;
  }
  while (total < N) {
    int best = -1;
    double best_r = std::numeric_limits<double>::infinity();
    for (int c = 0; c < C; ++c) {
      if (!(w[c] > 1e-3 * top)) continue;
      const double r = n[c] / (w[c] / sum);
      if (r < best_r) {
        best_r = r;
        best = c;
      }
    }
    ++n[best];
    ++total;
  }
  return n;
}

namespace {

// Designs keep this far (m) inside the pool so that the finer final check agrees.
constexpr double kTravelSafety = 0.01;

// Relative scaling of the DOF parameters at a design point.
Eigen::VectorXd Scale(const Eigen::VectorXd& theta) {
  Eigen::VectorXd d(theta.size());
  for (int i = 0; i < theta.size(); ++i) d[i] = theta[i] != 0.0 ? std::abs(theta[i]) : 1.0;
  return d;
}

Eigen::MatrixXd Rows(const Eigen::MatrixXd& M, const std::vector<int>& idx) {
  Eigen::MatrixXd out(idx.size(), idx.size());
  for (std::size_t a = 0; a < idx.size(); ++a) {
    for (std::size_t b = 0; b < idx.size(); ++b) out(a, b) = M(idx[a], idx[b]);
  }
  return out;
}

}  // namespace

DesignProblem SteadyWeightsProblem(const DofContext& ctx,
                                   const std::vector<std::vector<Eigen::MatrixXd>>& M, int N,
                                   const std::vector<Eigen::MatrixXd>& prior, Criterion criterion) {
  const int C = static_cast<int>(M.size());
  const int J = static_cast<int>(ctx.design_thetas().size());
  const int np = ctx.model().num_parameters();
  // Parameters reached by some candidate or the prior; m (index 0) is the nuisance.
  struct Data {
    std::vector<int> P, nuisance;                  // indices into P
    std::vector<std::vector<Eigen::MatrixXd>> Mc;  // [j][c] relative, on P
    std::vector<Eigen::MatrixXd> M0;               // [j] relative prior on P
    int N;
    Criterion criterion;
  };
  auto data = std::make_shared<Data>();
  data->N = N;
  data->criterion = criterion;
  Eigen::MatrixXd total = Eigen::MatrixXd::Zero(np, np);
  for (const auto& mc : M) total += RelativeInformation(mc[0], ctx.design_thetas()[0]);
  if (!prior.empty()) total += RelativeInformation(prior[0], ctx.design_thetas()[0]);
  data->P = InformedParameters(total);
  for (std::size_t a = 0; a < data->P.size(); ++a) {
    if (data->P[a] == 0) data->nuisance.push_back(static_cast<int>(a));
  }
  data->Mc.resize(J);
  data->M0.resize(J);
  for (int j = 0; j < J; ++j) {
    const Eigen::VectorXd d = Scale(ctx.design_thetas()[j]);
    for (int c = 0; c < C; ++c) {
      data->Mc[j].push_back(Rows(d.asDiagonal() * M[c][j] * d.asDiagonal(), data->P));
    }
    data->M0[j] = j < static_cast<int>(prior.size()) && prior[j].size() > 0
                      ? Rows(d.asDiagonal() * prior[j] * d.asDiagonal(), data->P)
                      : Eigen::MatrixXd::Zero(data->P.size(), data->P.size());
  }
  const bool use_gradient = criterion == Criterion::kD || criterion == Criterion::kDs;
  auto eval = [data, C, J](const double* w, double* phi, double* g, double* J_phi, double* J_g) {
    const int p = static_cast<int>(data->P.size());
    const bool nuis = data->criterion == Criterion::kDs && !data->nuisance.empty();
    double sw = 0.0;
    for (int c = 0; c < C; ++c) sw += w[c];
    g[0] = sw - 1.0;
    if (J_g) std::fill(J_g, J_g + C, 1.0);
    for (int j = 0; j < J; ++j) {
      // Ridge at the criteria's floor: finite values where some direction has weight 0.
      Eigen::MatrixXd Mw = data->M0[j] + kSingularFloor * Eigen::MatrixXd::Identity(p, p);
      for (int c = 0; c < C; ++c) Mw += data->N * w[c] * data->Mc[j][c];
      if (data->criterion == Criterion::kA || data->criterion == Criterion::kE) {
        std::vector<int> interest;  // every reached parameter but the nuisance m
        for (int a = 0; a < p; ++a) {
          if (std::find(data->nuisance.begin(), data->nuisance.end(), a) == data->nuisance.end()) {
            interest.push_back(a);
          }
        }
        phi[j] = EvaluateCriterion(Mw, data->criterion, interest).value;
        continue;
      }
      Eigen::LDLT<Eigen::MatrixXd> full(Mw);
      double v = full.vectorD().array().log().sum();
      Eigen::MatrixXd Mn;
      Eigen::LDLT<Eigen::MatrixXd> nn;
      if (nuis) {
        Mn = Rows(Mw, data->nuisance);
        nn.compute(Mn);
        v -= nn.vectorD().array().log().sum();
      }
      phi[j] = v;
      if (J_phi) {
        const Eigen::MatrixXd Minv = full.solve(Eigen::MatrixXd::Identity(p, p));
        Eigen::MatrixXd Nninv;
        if (nuis) Nninv = nn.solve(Eigen::MatrixXd::Identity(Mn.rows(), Mn.cols()));
        for (int c = 0; c < C; ++c) {
          double d = (Minv.cwiseProduct(data->Mc[j][c])).sum();
          if (nuis) d -= (Nninv.cwiseProduct(Rows(data->Mc[j][c], data->nuisance))).sum();
          J_phi[j * C + c] = data->N * d;
        }
      }
    }
    return true;
  };
  DesignProblem p;
  p.num_variables = C;
  p.lower.assign(C, 0.0);
  p.upper.assign(C, 1.0);
  p.x0.assign(C, 1.0 / std::max(1, C));
  p.num_scenarios = J;
  p.num_constraints = 1;
  p.evaluate = [eval](const double* w, double* phi, double* g) {
    return eval(w, phi, g, nullptr, nullptr);
  };
  if (use_gradient) p.evaluate_with_gradient = eval;
  return p;
}

namespace {

// A direction of a mapping: which thrusters work and which way each pushes.
std::map<int, int> ThrusterSigns(const model::Vehicle& v, const std::string& mapping,
                                 double force) {
  std::map<int, int> s;
  const int mi = v.MappingIndex(mapping);
  if (mi < 0) return s;
  for (const auto& [ti, share] : v.mappings[mi].shares) {
    if (share != 0.0 && force != 0.0) s[ti] = share * force > 0 ? 1 : -1;
  }
  return s;
}

bool Compatible(const std::map<int, int>& a, const std::map<int, int>& b) {
  for (const auto& [t, s] : b) {
    auto it = a.find(t);
    if (it != a.end() && it->second != s) return false;
  }
  return true;
}

class SteadyPlanner {
 public:
  SteadyPlanner(const DofContext& ctx, const SteadyDesignOptions& o) : ctx_(ctx), o_(o) {}

  // Hold time for measuring a speed of magnitude `speed` to speed_rel_sigma.
  double HoldTime(double speed) const {
    const auto& s = ctx_.sensors();
    const double target = o_.speed_rel_sigma * std::max(std::abs(speed), 1e-6);
    double t = std::numeric_limits<double>::infinity();
    if (s.position) {  // LS slope of N = rate·T positions: σ² = 12σ_p²/(rate·T³)
      t = std::min(t, std::cbrt(12.0 * s.position->sigma * s.position->sigma /
                                (s.position->rate_hz * target * target)));
    }
    if (s.velocity) {  // mean of N = rate·T velocities
      t = std::min(t,
                   s.velocity->sigma * s.velocity->sigma / (s.velocity->rate_hz * target * target));
    }
    return std::max(o_.min_hold_s, t);
  }

  struct Timing {
    bool settled = false;
    double settle_s = 0.0;                    // whole seconds
    double hold_s = 0.0;                      // whole seconds
    double min_speed = 0.0;                   // smallest |xi*| over the check grid
    double centre_speed = 0.0;                // xi* at the box centre
    double travel_lo = 0.0, travel_hi = 0.0;  // over the whole prefix + leg (settle + hold)
  };

  // Times `leg` after the segments `prefix` (from rest): settle from the prefix's end state.
  Timing TimeLeg(const std::vector<model::SegmentDesign>& prefix, const SteadyLeg& leg,
                 double horizon) const {
    model::TrialDesign d;
    d.dof = ctx_.dof();
    d.kind = model::TrialKind::kSegments;
    d.mapping = leg.mapping;
    double t0 = 0.0;
    for (const auto& s : prefix) {
      d.segments.push_back(s);
      t0 += s.duration;
    }
    d.segments.push_back({leg.force, horizon, leg.mapping});
    d.duration = t0 + horizon;
    const auto input = model::MakeExcitation(ctx_.vehicle(), d);
    const DofContext::TrialModel& tm = ctx_.ModelFor(d);
    const model::DofModel& m = *tm.model;
    const int ik = m.ParameterIndex(model::param::kLinearDrag);
    const int iq = m.ParameterIndex(model::param::kQuadraticDrag);
    const int ib = m.ParameterIndex(model::param::kBias);
    const int mi = ctx_.vehicle().MappingIndex(leg.mapping);
    const model::Direction dir = leg.force >= 0 ? model::Direction::kPos : model::Direction::kNeg;
    const int ie = mi >= 0 && !ctx_.vehicle().mappings[mi].IsOpenWater(dir)
                       ? m.ParameterIndex(model::EtaName(leg.mapping, dir))
                       : -1;
    auto steady = [&](const Eigen::VectorXd& th) {
      const double f = (ie >= 0 ? th[ie] : 1.0) * leg.force + (ib >= 0 ? th[ib] : 0.0);
      const double k = ik >= 0 ? th[ik] : 0.0, kq = iq >= 0 ? th[iq] : 0.0;
      return std::copysign(SteadySpeed(k, kq, std::abs(f)), f);
    };
    Timing out;
    out.settled = true;
    out.min_speed = std::numeric_limits<double>::infinity();
    out.centre_speed = steady(tm.design_thetas.front());
    const double dt = ctx_.step_s();
    std::vector<PositionTrace> traces;
    for (const auto& th : tm.check_thetas) {
      const double xs = steady(th);
      out.min_speed = std::min(out.min_speed, std::abs(xs));
      PositionTrace tr = TracePosition(m, th, *input, d.duration, dt, ctx_.step_s());
      // First sample after t0 from which the speed stays within the band.
      const double band = o_.settle_tolerance * std::abs(xs);
      std::size_t first = tr.velocity.size();
      for (std::size_t i = tr.velocity.size(); i-- > 0;) {
        if (i * dt < t0 - 1e-9) break;
        if (std::abs(tr.velocity[i] - xs) > band) break;
        first = i;
      }
      if (first >= tr.velocity.size() || first + 1 >= tr.velocity.size()) {
        out.settled = false;
      } else {
        out.settle_s = std::max(out.settle_s, first * dt - t0);
      }
      traces.push_back(std::move(tr));
    }
    if (!out.settled) return out;
    out.settle_s = std::ceil(out.settle_s - 1e-9);  // whole seconds for the pool team
    out.hold_s = std::ceil(HoldTime(out.min_speed) - 1e-9);
    const double end = t0 + out.settle_s + out.hold_s;
    for (const auto& tr : traces) {
      for (std::size_t i = 0; i < tr.position.size() && i * dt <= end + dt; ++i) {
        out.travel_lo = std::min(out.travel_lo, tr.position[i]);
        out.travel_hi = std::max(out.travel_hi, tr.position[i]);
      }
    }
    return out;
  }

  // A leg from rest at |force| in (mapping, sign), timed; travel = span over the box.
  bool MakeLeg(const std::string& mapping, int sign, double force_abs, SteadyLeg* leg) const {
    leg->mapping = mapping;
    leg->force = sign * force_abs;
    // Horizon: twice the settling time of the slowest linearised response (seed 000 eq. 13,
    // t_c = m/k_L at the heaviest, least-dragged box point) plus the longest hold; the full
    // trial limit only if that was not enough.
    const double t_max = ctx_.options().max_trial_duration_s;
    const int ik = ctx_.Index(model::param::kLinearDrag),
              iq = ctx_.Index(model::param::kQuadraticDrag);
    double tc = 0.0;
    for (const auto& th : ctx_.check_thetas()) {
      const double k = ik >= 0 ? th[ik] : 0.0, kq = iq >= 0 ? th[iq] : 0.0;
      const double kl = LinearisedDrag(k, kq, SteadySpeed(k, kq, 0.5 * force_abs));
      tc = std::max(tc, kl > 0 ? TimeConstant(th[0], kl) : t_max);
    }
    const double guess =
        2.0 * tc * std::log(1.0 / o_.settle_tolerance) + 2.0 * o_.min_hold_s + 30.0;
    Timing t = TimeLeg({}, *leg, std::min(t_max, guess));
    if (!t.settled && guess < t_max) t = TimeLeg({}, *leg, t_max);
    if (!t.settled) return false;
    leg->settle_s = t.settle_s;
    leg->hold_s = t.hold_s;
    leg->speed = t.centre_speed;
    leg->travel = t.travel_hi - t.travel_lo;
    return true;
  }

  // The smallest |force| in [lo, hi] whose run settles and holds within t_max: lo itself when
  // it does, else by bisection in log force (a short --max-duration: ROMEO surge's min_thrust
  // run takes 63 s, its 25 s runs at 183 N were refused with it). A larger force takes less
  // of both: it settles sooner (the linearised drag grows with the speed, seed 000 eq. 13) and
  // holds shorter (HoldTime ∝ 1/speed). False when none does.
  bool SmallestTimely(const std::string& mapping, int sign, double lo, double hi, double t_max,
                      double* force, SteadyLeg* leg) const {
    const auto timely = [&](double f, SteadyLeg* l) {
      return MakeLeg(mapping, sign, f, l) && l->duration() <= t_max;
    };
    *force = lo;
    if (timely(lo, leg)) return true;
    if (!timely(hi, leg)) return false;
    double a = std::log(lo), b = std::log(hi);  // a fails, b succeeds (its leg in *leg)
    *force = hi;
    for (int it = 0; it < 8; ++it) {
      const double c = 0.5 * (a + b);
      SteadyLeg l;
      if (timely(std::exp(c), &l)) {
        b = c;
        *force = std::exp(c);
        *leg = l;
      } else {
        a = c;
      }
    }
    return true;
  }

  const DofContext& ctx_;
  const SteadyDesignOptions& o_;
};

std::string DirName(const std::string& mapping, int sign) {
  return mapping + (sign > 0 ? " (phi > 0)" : " (phi < 0)");
}

}  // namespace

model::TrialDesign LegDesign(const SteadyLeg& leg, model::Dof dof, const std::string& id) {
  model::TrialDesign d;
  d.id = id;
  d.dof = dof;
  d.kind = model::TrialKind::kSteady;
  d.mapping = leg.mapping;
  d.force = leg.force;
  d.duration = leg.duration();
  return d;
}

SteadyCandidates MakeSteadyCandidates(const DofContext& ctx, const SteadyDesignOptions& o) {
  SteadyCandidates out;
  const auto& v = ctx.vehicle();
  SteadyPlanner sp(ctx, o);
  const double avail = ctx.available();
  const double t_max = ctx.options().max_trial_duration_s;
  std::ostringstream infeasible;
  for (int mi : v.MappingsOf(ctx.dof())) {
    const std::string& name = v.mappings[mi].name;
    for (int s : {+1, -1}) {
      const ForceRange r = ctx.ForceRangeFor(mi, s);
      if (!r.feasible) {
        infeasible << " " << r.reason << ";";
        continue;
      }
      double lo = r.min_abs * 1.02;  // a 2% margin over min_thrust
      SteadyLeg smallest;
      if (!sp.SmallestTimely(name, s, lo, r.max_abs, t_max, &lo, &smallest)) {
        infeasible << " " << DirName(name, s) << ": no run from " << model::Significant(lo, 4)
                   << " to " << model::Significant(r.max_abs, 4) << " "
                   << model::ForceUnit(ctx.dof()) << " settles and holds within " << t_max << " s;";
        continue;
      }
      out.required_travel = std::max(out.required_travel, smallest.travel);
      if (smallest.travel > avail - kTravelSafety) {
        std::ostringstream m;
        const model::Dof dof = ctx.dof();
        const bool turns = model::IsRotational(dof);
        const std::string unit(model::PositionUnit(dof));
        m << DirName(name, s) << ": the smallest run (|phi| = " << model::Significant(lo, 4) << " "
          << model::ForceUnit(dof) << ", settles in " << model::Significant(smallest.settle_s, 3)
          << " s, holds " << model::Significant(smallest.hold_s, 3) << " s) travels "
          << model::Significant(smallest.travel, 4) << " " << unit << " over the box; the "
          << (turns ? "tether allows " : "pool has ") << model::Significant(avail, 4) << " " << unit
          << (turns ? "" : " free") << ": needs "
          << model::Significant(ctx.pool().ExtentFor(dof, smallest.travel), 4)
          << (turns ? " turns (max_turns)" : " m wall to wall");
        infeasible << " " << m.str() << ";";
        continue;
      }
      // Largest force whose run from rest fits the pool (bisection in log force).
      double hi = r.max_abs;
      SteadyLeg big;
      const bool big_ok = sp.MakeLeg(name, s, hi, &big);
      if (!big_ok || big.travel > avail - kTravelSafety || big.duration() > t_max) {
        double a = std::log(lo), b = std::log(hi);
        for (int it = 0; it < 8; ++it) {
          const double c = 0.5 * (a + b);
          SteadyLeg leg;
          const bool ok = sp.MakeLeg(name, s, std::exp(c), &leg) &&
                          leg.travel <= avail - kTravelSafety && leg.duration() <= t_max;
          (ok ? a : b) = c;
        }
        hi = std::exp(a);
      }
      const int K = hi > lo * 1.05 ? o.levels : 1;
      for (int k = 0; k < K; ++k) {
        const double f = K == 1 ? lo : lo * std::pow(hi / lo, static_cast<double>(k) / (K - 1));
        SteadyLeg leg;
        if (sp.MakeLeg(name, s, f, &leg) && leg.travel <= avail - kTravelSafety &&
            leg.duration() <= t_max) {
          out.legs.push_back(leg);
        }
      }
    }
  }
  out.infeasible = infeasible.str();
  return out;
}

namespace {

// Step 2: the information of each candidate from rest (M[c][j] at design point j).
std::vector<std::vector<Eigen::MatrixXd>> CandidateInformation(const DofContext& ctx,
                                                               const std::vector<SteadyLeg>& legs) {
  std::vector<std::vector<Eigen::MatrixXd>> M;
  for (const SteadyLeg& leg : legs) {
    model::TrialDesign d;
    d.dof = ctx.dof();
    d.kind = model::TrialKind::kSteady;
    d.mapping = leg.mapping;
    d.force = leg.force;
    d.duration = leg.duration();
    M.push_back(ctx.Information(d));
  }
  return M;
}

// Number of legs: the options', or every informed parameter but m plus 2.
int LegCount(const DofContext& ctx, const SteadyDesignOptions& o,
             const std::vector<std::vector<Eigen::MatrixXd>>& M) {
  if (o.legs != 0) return o.legs;
  const int np = ctx.model().num_parameters();
  Eigen::MatrixXd total = Eigen::MatrixXd::Zero(np, np);
  for (const auto& m : M) total += RelativeInformation(m[0], ctx.design_thetas()[0]);
  return static_cast<int>(InformedParameters(total).size()) - 1 + 2;
}

// Step 2: the approximate design's weights; false (status and message set) if it failed.
bool SolveWeights(const DofContext& ctx, const SteadyDesignOptions& o,
                  const std::vector<std::vector<Eigen::MatrixXd>>& M, int N,
                  const std::vector<Eigen::MatrixXd>& prior, SteadyDesignResult* result) {
  const DesignProblem problem = SteadyWeightsProblem(ctx, M, N, prior, o.criterion);
  SolverOptions so = ctx.options().solver;
  so.robustness = ctx.options().robustness;
  so.global = GlobalMethod::kNone;  // concave: a local method finds the global optimum
  so.max_local_evaluations = std::max(so.max_local_evaluations, 200);
  result->summary = Solve(ctx.options().steady_backend, problem, so);
  if (!result->summary.is_success()) {
    result->status = DesignStatus::kFailed;
    result->message = "approximate design: " + result->summary.BriefReport();
    return false;
  }
  result->weights = result->summary.x;
  return true;
}

// Step 3: efficient rounding of N·w; every direction with weight keeps a leg.
std::vector<SteadyLeg> ExactDesign(const std::vector<SteadyLeg>& candidates,
                                   const std::vector<double>& weights, int N) {
  std::vector<int> n = EfficientRounding(weights, N);
  const double wmax = *std::max_element(weights.begin(), weights.end());
  std::map<std::string, int> best_in_dir;  // direction -> candidate with the largest weight
  std::map<std::string, int> legs_in_dir;
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    const std::string key = DirName(candidates[c].mapping, candidates[c].force > 0 ? 1 : -1);
    if (weights[c] > 1e-3 * wmax &&
        (!best_in_dir.count(key) || weights[c] > weights[best_in_dir[key]])) {
      best_in_dir[key] = static_cast<int>(c);
    }
    legs_in_dir[key] += n[c];
  }
  for (const auto& [key, c] : best_in_dir) {
    if (legs_in_dir[key] == 0) ++n[c];
  }
  std::vector<SteadyLeg> legs;
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    for (int k = 0; k < n[c]; ++k) legs.push_back(candidates[c]);
  }
  return legs;
}

// Step 4: packs legs into trials, each a chain of legs alternating in direction, in
// compatible thrusters, within the pool and the trial duration limit.
class LegPacker {
 public:
  LegPacker(const DofContext& ctx, const SteadyDesignOptions& o, std::vector<SteadyLeg> legs)
      : ctx_(ctx), o_(o), planner_(ctx, o), remaining_(std::move(legs)) {
    std::sort(remaining_.begin(), remaining_.end(),
              [](const SteadyLeg& a, const SteadyLeg& b) { return a.travel > b.travel; });
  }

  bool done() const { return remaining_.empty(); }

  /// The next trial: the longest-travelling leg left, then legs chained after it.
  model::TrialDesign NextTrial(const std::string& id) {
    chain_ = {remaining_.front()};
    remaining_.erase(remaining_.begin());
    signs_ = ThrusterSigns(ctx_.vehicle(), chain_[0].mapping, chain_[0].force);
    segs_ = {{chain_[0].force, chain_[0].duration(), chain_[0].mapping}};
    total_ = chain_[0].duration();
    tried_.assign(remaining_.size(), false);
    while (static_cast<int>(chain_.size()) < o_.max_legs_per_trial) {
      const int pick = PickNext();
      if (pick < 0) break;
      tried_[pick] = true;
      TryChain(pick);
    }
    return ChainDesign(id);
  }

 private:
  // A leg left, not tried for this chain, moving against the chain's last leg in compatible
  // thrusters, with the closest travel; -1 if none.
  int PickNext() const {
    const double dir = chain_.back().speed;
    int pick = -1;
    for (std::size_t r = 0; r < remaining_.size(); ++r) {
      if (tried_[r] || remaining_[r].speed * dir >= 0) continue;
      if (!Compatible(signs_,
                      ThrusterSigns(ctx_.vehicle(), remaining_[r].mapping, remaining_[r].force))) {
        continue;
      }
      if (pick < 0 || std::abs(remaining_[r].travel - chain_.back().travel) <
                          std::abs(remaining_[pick].travel - chain_.back().travel)) {
        pick = static_cast<int>(r);
      }
    }
    return pick;
  }

  // Appends leg `pick` (timed after the chain so far) if the trial stays feasible.
  void TryChain(int pick) {
    const double t_max = ctx_.options().max_trial_duration_s;
    SteadyLeg leg = remaining_[pick];
    const SteadyPlanner::Timing t = planner_.TimeLeg(segs_, leg, t_max);
    if (!t.settled) return;
    leg.settle_s = t.settle_s;
    leg.hold_s = t.hold_s;
    if (total_ + leg.duration() > t_max) return;
    if (t.travel_hi - t.travel_lo > ctx_.available() - kTravelSafety) return;
    std::vector<model::SegmentDesign> trial_segs = segs_;
    trial_segs.push_back({leg.force, leg.duration(), leg.mapping});
    model::TrialDesign d;
    d.dof = ctx_.dof();
    d.kind = model::TrialKind::kSegments;
    d.mapping = chain_[0].mapping;
    d.segments = trial_segs;
    d.duration = total_ + leg.duration();
    if (!ctx_.Check(d).feasible) return;
    chain_.push_back(leg);
    segs_ = trial_segs;
    total_ += leg.duration();
    for (const auto& [th, s] : ThrusterSigns(ctx_.vehicle(), leg.mapping, leg.force)) {
      signs_[th] = s;
    }
    remaining_.erase(remaining_.begin() + pick);
    tried_.erase(tried_.begin() + pick);
  }

  // The chain as a steady trial (one leg) or a segments trial.
  model::TrialDesign ChainDesign(const std::string& id) const {
    model::TrialDesign d;
    d.id = id;
    d.dof = ctx_.dof();
    d.mapping = chain_[0].mapping;
    d.duration = total_;
    if (chain_.size() == 1) {
      d.kind = model::TrialKind::kSteady;
      d.force = chain_[0].force;
      return d;
    }
    d.kind = model::TrialKind::kSegments;
    for (auto s : segs_) {
      if (s.mapping == d.mapping) s.mapping.clear();  // the trial's mapping
      d.segments.push_back(s);
    }
    return d;
  }

  const DofContext& ctx_;
  const SteadyDesignOptions& o_;
  SteadyPlanner planner_;
  std::vector<SteadyLeg> remaining_;
  std::vector<SteadyLeg> chain_;
  std::map<int, int> signs_;
  std::vector<model::SegmentDesign> segs_;
  double total_ = 0.0;
  std::vector<bool> tried_;
};

void PackTrials(const DofContext& ctx, const SteadyDesignOptions& o, const std::string& id_prefix,
                SteadyDesignResult* result) {
  LegPacker packer(ctx, o, result->legs);
  const int np = ctx.model().num_parameters();
  result->information.assign(ctx.design_thetas().size(), Eigen::MatrixXd::Zero(np, np));
  int trial_no = 0;
  while (!packer.done()) {
    PlannedTrial trial;
    trial.design = packer.NextTrial(id_prefix + "-" + std::to_string(++trial_no));
    const TrialCheck check = ctx.Check(trial.design);
    trial.travel = check.travel;
    trial.thrust_min = check.thrust_min;
    const auto info = ctx.Information(trial.design);
    for (std::size_t j = 0; j < info.size(); ++j) result->information[j] += info[j];
    result->trials.push_back(trial);
    result->checks.push_back(check);
  }
}

// A leg the exact design runs more than once is a replicate, not a slip: the D-optimal
// weights put that share of the N legs on it (efficient rounding of N·w, Pukelsheim & Rieder
// 1992), so a schedule may list the same run twice.
void NoteReplicates(const DofContext& ctx, const std::vector<SteadyLeg>& legs, int N,
                    SteadyDesignResult* result) {
  std::map<std::pair<std::string, double>, int> count;
  for (const SteadyLeg& l : legs) ++count[{l.mapping, l.force}];
  for (const auto& [leg, n] : count) {
    if (n < 2) continue;
    result->notes.push_back(std::string(model::DofName(ctx.dof())) + ": the steady run " +
                            DirName(leg.first, leg.second > 0 ? 1 : -1) + " at " +
                            model::Significant(leg.second, 3) + " " +
                            std::string(model::ForceUnit(ctx.dof())) + " runs " +
                            std::to_string(n) + " times: the D-optimal design puts " +
                            std::to_string(n) + " of its " + std::to_string(N) +
                            " legs there (replicates, not a repeated entry)");
  }
}

// The criterion of the packed trials with the prior, and the status and notes.
void Summarise(const DofContext& ctx, const SteadyDesignOptions& o,
               const std::vector<Eigen::MatrixXd>& prior, const std::string& infeasible,
               SteadyDesignResult* result) {
  const std::string dof(model::DofName(ctx.dof()));
  std::vector<Eigen::MatrixXd> total = result->information;
  for (std::size_t j = 0; j < total.size() && j < prior.size(); ++j) {
    if (prior[j].size() == total[j].size()) total[j] += prior[j];
  }
  std::vector<int> interest;
  for (int i : InformedParameters(RelativeInformation(total[0], ctx.design_thetas()[0]))) {
    if (i != 0) interest.push_back(i);
  }
  bool singular = false;
  result->criterion_per_point = ctx.CriterionValues(total, o.criterion, interest, &singular);
  result->criterion = Aggregate(ctx.options().robustness, result->criterion_per_point);
  bool all_ok = true;
  for (const auto& c : result->checks) all_ok = all_ok && c.feasible;
  if (!all_ok) {
    result->status = DesignStatus::kInfeasible;
    result->message = "a packed steady trial violates a hard constraint";
    return;
  }
  result->status = DesignStatus::kOk;
  if (singular) {
    result->notes.push_back(dof +
                            ": the steady runs alone leave a combination of drag, bias "
                            "and eta undetermined; the other trials must resolve it");
  }
  if (!infeasible.empty()) {
    result->notes.push_back(dof + ": some directions cannot be run in this pool:" + infeasible);
  }
}

}  // namespace

SteadyDesignResult DesignSteady(const DofContext& ctx, const SteadyDesignOptions& o,
                                const std::vector<Eigen::MatrixXd>& prior,
                                const std::string& id_prefix) {
  SteadyDesignResult result;
  std::string error;
  if (!o.IsValid(&error) || !ctx.options().IsValid(&error)) {
    result.message = error;
    return result;
  }
  // 1. Candidates per mapping and direction.
  SteadyCandidates cands = MakeSteadyCandidates(ctx, o);
  result.candidates = cands.legs;
  result.required_travel = cands.required_travel;
  for (const auto& n : cands.notes) result.notes.push_back(n);
  if (result.candidates.empty()) {
    result.status = DesignStatus::kInfeasible;
    result.message =
        "no steady run of " + std::string(model::DofName(ctx.dof())) + " fits:" + cands.infeasible;
    return result;
  }
  // 2. Information of each candidate from rest, and the approximate design.
  const auto M = CandidateInformation(ctx, result.candidates);
  const int N = LegCount(ctx, o, M);
  if (!SolveWeights(ctx, o, M, N, prior, &result)) return result;
  // 3. Exact design.
  result.legs = ExactDesign(result.candidates, result.weights, N);
  if (result.legs.empty()) {
    result.status = DesignStatus::kFailed;
    result.message =
        "approximate design without support (no positive weight): " + result.summary.BriefReport();
    return result;
  }
  // 4. Pack legs into trials: alternate directions, compatible thrusters, within the pool.
  PackTrials(ctx, o, id_prefix, &result);
  Summarise(ctx, o, prior, cands.infeasible, &result);
  NoteReplicates(ctx, result.legs, N, &result);
  return result;
}

}  // namespace uuvplan::planner
