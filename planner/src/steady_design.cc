// Steady-state runs and their legs (see steady_design.h).
#include "uuvplan/planner/steady_design.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <sstream>

#include "uuvplan/model/effects.h"
#include "uuvplan/model/mapping.h"
#include "uuvplan/planner/fisher_information.h"
#include "uuvplan/planner/seed_rules.h"
#include "uuvplan/planner/thrust_limits.h"

namespace uuvplan::planner {

bool SteadyDesignOptions::IsValid(std::string* error) const {
  auto fail = [&](const std::string& m) {
    if (error) *error = m;
    return false;
  };
  if (legs < 0)
    return fail("SteadyDesignOptions::legs = " + std::to_string(legs) +
                ". Violated constraint: >= 0");
  if (levels < 1)
    return fail("SteadyDesignOptions::levels = " + std::to_string(levels) +
                ". Violated constraint: >= 1");
  if (!(settle_tolerance > 0 && settle_tolerance < 1)) {
    return fail("SteadyDesignOptions::settle_tolerance = " + std::to_string(settle_tolerance) +
                ". Violated constraint: 0 < tol < 1");
  }
  if (!(min_hold_s > 0))
    return fail("SteadyDesignOptions::min_hold_s = " + std::to_string(min_hold_s) +
                ". Violated constraint: > 0");
  if (!(speed_rel_sigma > 0)) {
    return fail("SteadyDesignOptions::speed_rel_sigma = " + std::to_string(speed_rel_sigma) +
                ". Violated constraint: > 0");
  }
  if (max_legs_per_trial < 1) {
    return fail("SteadyDesignOptions::max_legs_per_trial = " + std::to_string(max_legs_per_trial) +
                ". Violated constraint: >= 1");
  }
  return true;
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

  const DofContext& ctx_;
  const SteadyDesignOptions& o_;
};

std::string DirName(const std::string& mapping, int sign) {
  return mapping + (sign > 0 ? " (phi > 0)" : " (phi < 0)");
}

}  // namespace

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
      const double lo = r.min_abs * 1.02;  // a 2% margin over min_thrust
      SteadyLeg smallest;
      if (!sp.MakeLeg(name, s, lo, &smallest)) {
        infeasible << " " << DirName(name, s) << ": does not settle within " << t_max << " s;";
        continue;
      }
      out.required_travel = std::max(out.required_travel, smallest.travel);
      if (smallest.travel > avail - kTravelSafety) {
        std::ostringstream m;
        m << DirName(name, s) << ": the smallest run (|phi| = " << lo << ", settles in "
          << smallest.settle_s << " s, holds " << smallest.hold_s << " s) travels "
          << smallest.travel << " over the box; the pool has " << avail << " free: needs "
          << smallest.travel + 2 * ctx.pool().margin << " with its margins";
        infeasible << " " << m.str() << ";";
        continue;
      }
      if (smallest.duration() > t_max) {
        infeasible << " " << DirName(name, s) << ": settling and holding take "
                   << smallest.duration() << " s, beyond the " << t_max << " s trial limit;";
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

SteadyDesignResult DesignSteady(const DofContext& ctx, const SteadyDesignOptions& o,
                                const std::vector<Eigen::MatrixXd>& prior,
                                const std::string& id_prefix) {
  SteadyDesignResult result;
  std::string error;
  if (!o.IsValid(&error) || !ctx.options().IsValid(&error)) {
    result.message = error;
    return result;
  }
  const auto& v = ctx.vehicle();
  SteadyPlanner sp(ctx, o);
  const double avail = ctx.available();
  const double t_max = ctx.options().max_trial_duration_s;
  const std::string dof(model::DofName(ctx.dof()));

  // 1. Candidates per mapping and direction.
  SteadyCandidates cands = MakeSteadyCandidates(ctx, o);
  result.candidates = cands.legs;
  result.required_travel = cands.required_travel;
  for (const auto& n : cands.notes) result.notes.push_back(n);
  std::ostringstream infeasible;
  infeasible << cands.infeasible;
  if (result.candidates.empty()) {
    result.status = DesignStatus::kInfeasible;
    result.message = "no steady run of " + dof + " fits:" + infeasible.str();
    return result;
  }

  // 2. Information of each candidate from rest, and the approximate design.
  const int C = static_cast<int>(result.candidates.size());
  std::vector<std::vector<Eigen::MatrixXd>> M(C);
  for (int c = 0; c < C; ++c) {
    const SteadyLeg& leg = result.candidates[c];
    model::TrialDesign d;
    d.dof = ctx.dof();
    d.kind = model::TrialKind::kSteady;
    d.mapping = leg.mapping;
    d.force = leg.force;
    d.duration = leg.duration();
    M[c] = ctx.Information(d);
  }
  int N = o.legs;
  if (N == 0) {
    Eigen::MatrixXd total =
        Eigen::MatrixXd::Zero(ctx.model().num_parameters(), ctx.model().num_parameters());
    for (const auto& m : M) total += RelativeInformation(m[0], ctx.design_thetas()[0]);
    N = static_cast<int>(InformedParameters(total).size()) - 1 + 2;  // all but m, plus 2
  }
  const DesignProblem problem = SteadyWeightsProblem(ctx, M, N, prior, o.criterion);
  SolverOptions so = ctx.options().solver;
  so.robustness = ctx.options().robustness;
  so.global = GlobalMethod::kNone;  // concave: a local method finds the global optimum
  so.max_local_evaluations = std::max(so.max_local_evaluations, 200);
  result.summary = Solve(ctx.options().steady_backend, problem, so);
  if (!result.summary.is_success()) {
    result.status = DesignStatus::kFailed;
    result.message = "approximate design: " + result.summary.BriefReport();
    return result;
  }
  result.weights = result.summary.x;

  // 3. Exact design: efficient rounding; every direction with weight keeps a leg.
  std::vector<int> n = EfficientRounding(result.weights, N);
  const double wmax = *std::max_element(result.weights.begin(), result.weights.end());
  std::map<std::string, int> best_in_dir;  // direction -> candidate with the largest weight
  std::map<std::string, int> legs_in_dir;
  for (int c = 0; c < C; ++c) {
    const std::string key =
        DirName(result.candidates[c].mapping, result.candidates[c].force > 0 ? 1 : -1);
    if (result.weights[c] > 1e-3 * wmax &&
        (!best_in_dir.count(key) || result.weights[c] > result.weights[best_in_dir[key]])) {
      best_in_dir[key] = c;
    }
    legs_in_dir[key] += n[c];
  }
  for (const auto& [key, c] : best_in_dir) {
    if (legs_in_dir[key] == 0) ++n[c];
  }
  for (int c = 0; c < C; ++c) {
    for (int k = 0; k < n[c]; ++k) result.legs.push_back(result.candidates[c]);
  }
  if (result.legs.empty()) {
    result.status = DesignStatus::kFailed;
    result.message =
        "approximate design without support (no positive weight): " + result.summary.BriefReport();
    return result;
  }

  // 4. Pack legs into trials: alternate directions, compatible thrusters, within the pool.
  std::vector<SteadyLeg> remaining = result.legs;
  std::sort(remaining.begin(), remaining.end(),
            [](const SteadyLeg& a, const SteadyLeg& b) { return a.travel > b.travel; });
  int trial_no = 0;
  const int np = ctx.model().num_parameters();
  result.information.assign(ctx.design_thetas().size(), Eigen::MatrixXd::Zero(np, np));
  while (!remaining.empty()) {
    std::vector<SteadyLeg> chain = {remaining.front()};
    remaining.erase(remaining.begin());
    std::map<int, int> signs = ThrusterSigns(v, chain[0].mapping, chain[0].force);
    std::vector<model::SegmentDesign> segs = {
        {chain[0].force, chain[0].duration(), chain[0].mapping}};
    double total = chain[0].duration();
    std::vector<bool> tried(remaining.size(), false);
    while (static_cast<int>(chain.size()) < o.max_legs_per_trial) {
      const double dir = chain.back().speed;
      int pick = -1;
      for (std::size_t r = 0; r < remaining.size(); ++r) {
        if (tried[r] || remaining[r].speed * dir >= 0) continue;
        if (!Compatible(signs, ThrusterSigns(v, remaining[r].mapping, remaining[r].force)))
          continue;
        if (pick < 0 || std::abs(remaining[r].travel - chain.back().travel) <
                            std::abs(remaining[pick].travel - chain.back().travel)) {
          pick = static_cast<int>(r);
        }
      }
      if (pick < 0) break;
      tried[pick] = true;
      SteadyLeg leg = remaining[pick];
      const SteadyPlanner::Timing t = sp.TimeLeg(segs, leg, t_max);
      if (!t.settled) continue;
      leg.settle_s = t.settle_s;
      leg.hold_s = t.hold_s;
      if (total + leg.duration() > t_max) continue;
      if (t.travel_hi - t.travel_lo > avail - kTravelSafety) continue;
      std::vector<model::SegmentDesign> trial_segs = segs;
      trial_segs.push_back({leg.force, leg.duration(), leg.mapping});
      model::TrialDesign d;
      d.dof = ctx.dof();
      d.kind = model::TrialKind::kSegments;
      d.mapping = chain[0].mapping;
      d.segments = trial_segs;
      d.duration = total + leg.duration();
      if (!ctx.Check(d).feasible) continue;
      chain.push_back(leg);
      segs = trial_segs;
      total += leg.duration();
      for (const auto& [th, s] : ThrusterSigns(v, leg.mapping, leg.force)) signs[th] = s;
      remaining.erase(remaining.begin() + pick);
      tried.erase(tried.begin() + pick);
    }
    PlannedTrial trial;
    model::TrialDesign& d = trial.design;
    d.id = id_prefix + "-" + std::to_string(++trial_no);
    d.dof = ctx.dof();
    d.mapping = chain[0].mapping;
    d.duration = total;
    if (chain.size() == 1) {
      d.kind = model::TrialKind::kSteady;
      d.force = chain[0].force;
    } else {
      d.kind = model::TrialKind::kSegments;
      for (auto s : segs) {
        if (s.mapping == d.mapping) s.mapping.clear();  // the trial's mapping
        d.segments.push_back(s);
      }
    }
    const TrialCheck check = ctx.Check(d);
    trial.travel = check.travel;
    trial.thrust_min = check.thrust_min;
    const auto info = ctx.Information(d);
    for (std::size_t j = 0; j < info.size(); ++j) result.information[j] += info[j];
    result.trials.push_back(trial);
    result.checks.push_back(check);
  }

  std::vector<Eigen::MatrixXd> total = result.information;
  for (std::size_t j = 0; j < total.size() && j < prior.size(); ++j) {
    if (prior[j].size() == total[j].size()) total[j] += prior[j];
  }
  std::vector<int> interest;
  for (int i : InformedParameters(RelativeInformation(total[0], ctx.design_thetas()[0]))) {
    if (i != 0) interest.push_back(i);
  }
  bool singular = false;
  result.criterion_per_point = ctx.CriterionValues(total, o.criterion, interest, &singular);
  result.criterion = Aggregate(ctx.options().robustness, result.criterion_per_point);
  bool all_ok = true;
  for (const auto& c : result.checks) all_ok = all_ok && c.feasible;
  if (!all_ok) {
    result.status = DesignStatus::kInfeasible;
    result.message = "a packed steady trial violates a hard constraint";
  } else {
    result.status = DesignStatus::kOk;
    if (singular) {
      result.notes.push_back(dof +
                             ": the steady runs alone leave a combination of drag, bias "
                             "and eta undetermined; the other trials must resolve it");
    }
    if (!infeasible.str().empty()) {
      result.notes.push_back(dof +
                             ": some directions cannot be run in this pool:" + infeasible.str());
    }
  }
  return result;
}

}  // namespace uuvplan::planner
