#include "core/coupled_equilibrium.h"

#include <Eigen/LU>
#include <Eigen/QR>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/chain_guess.h"
#include "core/coarse_guess.h"
#include "core/error.h"
#include "core/forces.h"

namespace cablefilm {
namespace {

// The round-off of the lines' end forces that a balance may be within, at most, of the lines'
// load (their floors': see `balanced` below).
constexpr double kMostFloor = 1e-5;

}  // namespace

Vec StaticStationForce(const LineModel& m, const State& s, int j) {
  const Water water = SceneWater(m);
  ForceWorkspace ws(m.line.links);
  ComputeGeometry(m, water, 0.0, s.x, ws.geometry);
  ComputeHookeTensions(m, ws.geometry, ws.tension);
  ComputeStationForces(m, water, ws.geometry, ws.tension, Points::Zero(kDim, m.stations()),
                       ws.force);
  return ws.force.col(j);
}

namespace {

// The lines' load on body b at `pose`, the force on line i's station j given by force(i, j).
template <class Force>
Vec6 LinesLoad(const Model& sys, const std::vector<State>& states, int b, const Vec6& pose,
               const Force& force) {
  Vec6 load = Vec6::Zero();
  const Vec r = pose.head<3>();
  for (const Point& p : sys.points) {
    if (p.on_body != b) continue;
    for (const LineEnd& e : p.ends)
      load += LoadAbout(r, states[e.line].x.col(e.station), force(e.line, e.station));
  }
  return load;
}

// The unknowns: kDim per shared point (its position), then 6 per free body (its pose), as
// groups; a group moves the lines with an end at its point or at a point on its body.
struct Unknowns {
  struct Group {
    int offset = 0, size = 0;  // in the vector of unknowns
    int point = -1, body = -1;
    double limit = 1e300;      // the shortest of its lines [m]: a Newton step moves it (and a
                               // body's farthest point) at most a tenth of that
    double radius = 1;         // a body's size: its farthest point from its reference, >= 1 [m]
  };
  std::vector<Group> groups;
  int size = 0;

  explicit Unknowns(const Model& sys) {
    for (int p : sys.shared_points) {
      Group g{size, kDim, p, -1};
      for (const LineEnd& e : sys.points[p].ends)
        g.limit = std::min(g.limit, sys.lines[e.line].line.total_length());
      groups.push_back(g);
      size += g.size;
    }
    for (int b : sys.free_bodies) {
      Group g{size, 6, -1, b};
      for (const Point& p : sys.points) {
        if (p.on_body != b) continue;
        g.radius = std::max(g.radius, p.local.norm());
        for (const LineEnd& e : p.ends)
          g.limit = std::min(g.limit, sys.lines[e.line].line.total_length());
      }
      groups.push_back(g);
      size += g.size;
    }
  }

  // Whether group k moves an end of line i.
  bool Moves(const Model& sys, int k, int i) const {
    for (int e = 0; e < 2; ++e) {
      const int at = sys.line_points[i][e];
      if (at == groups[k].point) return true;
      if (groups[k].body >= 0 && sys.points[at].on_body == groups[k].body) return true;
    }
    return false;
  }
};

// The lines with their ends at shared points held where the unknowns X put those points, and
// their ends on free bodies where X puts the bodies; and their equilibria.
class HeldLines {
 public:
  // `models`: sys's lines (or a copy of them), held where they are: their ends moved where the
  // unknowns put them, and put back as they were when it goes (no copy of a long line's model,
  // some 0.35 kB a station).
  HeldLines(const Model& sys, std::vector<LineModel>& models, const Unknowns& u,
            const EquilibriumOptions& options)
      : sys_(sys), u_(u), models_(models), states_(sys.lines.size()),
        reports_(sys.lines.size()), forces_(sys.lines.size()), held_at_(sys.lines.size(), Unknown()),
        known_(sys.lines.size(), 0),
        line_work_(sys.lines.size(), 0.0), most_work_(options.max_line_work),
        work_(options.line_work ? options.line_work : &own_work_) {
    for (const LineModel& m : models_) ends_.push_back(m.ends);
    line_options_.cancel = options.cancel;
    // Each solve on its own count, within the bound (a line too large for it is refused at
    // once: StaticsWorkError); their sum against the same bound after each.
    line_options_.max_work = options.max_line_statics;
  }
  ~HeldLines() {
    for (std::size_t i = 0; i < models_.size(); ++i) models_[i].ends = ends_[i];
  }
  HeldLines(const HeldLines&) = delete;
  HeldLines& operator=(const HeldLines&) = delete;

  // The lines' states and their end stations' forces, as a step's trial may need them back.
  struct Kept {
    std::vector<State> states;
    std::vector<std::array<Vec, 2>> forces, held_at;
    std::vector<char> known;
  };
  Kept Keep() const { return Kept{states_, forces_, held_at_, known_}; }
  void Restore(const Kept& kept) {
    states_ = kept.states;
    forces_ = kept.forces;
    held_at_ = kept.held_at;
    known_ = kept.known;
  }

  static constexpr int kAll = -1;    // every line
  static constexpr int kMoved = -2;  // the lines that some unknown moves

  // Places the unknowns at X and solves the lines that group `group` moves (or kAll, kMoved).
  void Solve(const Eigen::VectorXd& X, int group) {
    const int groups = static_cast<int>(u_.groups.size());
    for (int i = 0; i < static_cast<int>(models_.size()); ++i) {
      bool moved = false;
      for (int k = 0; k < groups; ++k)
        if (u_.Moves(sys_, k, i)) moved = true, Place(X, k, i);
      if (group == kMoved && !moved) continue;
      if (group >= 0 && !u_.Moves(sys_, group, i)) continue;
      // Held where its state was solved (a body turned about the point the line hangs from):
      // that state, not a solve that stirs its round-off into the Jacobian's column.
      if (HeldAt(i) == held_at_[i]) continue;
      try {
        states_[i] = SolveHeld(i);
        held_at_[i] = HeldAt(i);
        HoldForces(i);
      } catch (const CancelledError&) {
        throw;
      } catch (const StaticsWorkError& e) {
        throw StaticsWorkError("line \"" + sys_.line_names[i] + "\": " + e.what());
      } catch (const Error& e) {
        throw Error("line \"" + sys_.line_names[i] + "\": no static equilibrium: " + e.what());
      }
      if (*work_ > most_work_) {
        const int most = static_cast<int>(std::max_element(line_work_.begin(), line_work_.end()) -
                                          line_work_.begin());
        std::ostringstream os;
        os << "the shared points and free bodies of the system were not balanced within "
           << most_work_ << " station-passes of their lines' equilibria (each residual, step "
           << "along the links and Newton matrix counts its line's stations); line \""
           << sys_.line_names[most] << "\" (" << models_[most].stations()
           << " stations) took the most, " << line_work_[most] / models_[most].stations()
           << " passes in all";
        throw Error(os.str());
      }
    }
  }
  double work() const { return *work_; }
  void AddWork(double work) { *work_ += work; }  // [station-passes]

  // The out-of-balance load of each group at X: the net force on a shared point [N], the net
  // force and moment on a free body [N, N m about its reference point].
  Eigen::VectorXd Residual(const Eigen::VectorXd& X) const {
    Eigen::VectorXd R = Eigen::VectorXd::Zero(u_.size);
    for (const Unknowns::Group& g : u_.groups) {
      if (g.point >= 0) {
        for (const LineEnd& e : sys_.points[g.point].ends)
          R.segment<kDim>(g.offset) += Force(e.line, e.station);
        continue;
      }
      const Vec6 pose = X.segment<6>(g.offset);
      const BodySpec& body = sys_.bodies[g.body];
      R.segment<6>(g.offset) =
          LinesLoad(sys_, states_, g.body, pose,
                    [&](int i, int j) { return Force(i, j); }) +
          BodyOwnLoads(body, pose, sys_.env.fluid_density, sys_.env.gravity) + CurrentDrag(body, pose);
    }
    return R;
  }

  // The current's drag on a body held at `pose` (its quadratic damping at rest in the flow,
  // as in time) [N].
  Vec6 CurrentDrag(const BodySpec& body, const Vec6& pose) const {
    if (models_.empty()) return Vec6::Zero();
    const LineModel& m = models_[0];
    return BodyDampingLoad(body, Vec6::Zero(), CurrentAt(m, SceneWater(m), pose[kVertical]));
  }

  const std::vector<State>& states() const { return states_; }
  const std::vector<LineEquilibriumReport>& reports() const { return reports_; }
  // States from elsewhere (a guess, the chains'): their end forces found when asked.
  void Restore(std::vector<State> states) {
    states_ = std::move(states);
    std::fill(known_.begin(), known_.end(), 0);
    std::fill(held_at_.begin(), held_at_.end(), Unknown());
  }

 private:
  // The force on station j (an end) of line i held in its state [N]: as its solve left it
  // (the force on an end station, in its water without waves: StaticStationForce's without
  // waves, in one pass less), else StaticStationForce's.
  Vec Force(int i, int j) const {
    if (!known_[i]) {
      forces_[i][0] = StaticStationForce(models_[i], states_[i], 0);
      forces_[i][1] = StaticStationForce(models_[i], states_[i], models_[i].line.links);
      known_[i] = 1;
    }
    return forces_[i][j == 0 ? 0 : 1];
  }
  // Where line i's ends are held: a prescribed end's position at t = 0 [m], a free end's
  // infinity; Unknown() (NaN, equal to nothing) for a state not solved here.
  std::array<Vec, 2> HeldAt(int i) const {
    auto at = [](const EndMotion& e) {
      return e.prescribed() ? e.Position(0)
                            : Vec::Constant(std::numeric_limits<double>::infinity());
    };
    return {at(models_[i].ends.start), at(models_[i].ends.end)};
  }
  static std::array<Vec, 2> Unknown() {
    const Vec nan = Vec::Constant(std::numeric_limits<double>::quiet_NaN());
    return {nan, nan};
  }
  void HoldForces(int i) {
    known_[i] = !models_[i].has_waves();
    forces_[i] = {reports_[i].start_force, reports_[i].end_force};
  }

  // Line i's ends at group k's point or body, where X puts them.
  void Place(const Eigen::VectorXd& X, int k, int i) {
    const Unknowns::Group& g = u_.groups[k];
    if (g.body >= 0) {
      PlaceBodyEnds(sys_, g.body, X.segment<6>(g.offset), i, models_[i]);
      return;
    }
    for (int e = 0; e < 2; ++e)
      if (sys_.line_points[i][e] == g.point)
        (e == 0 ? models_[i].ends.start : models_[i].ends.end) =
            EndMotion::Fixed(X.segment<kDim>(g.offset));
  }

  // Line i's equilibrium: from its last one moved with its ends (warm), or when there is none
  // or that fails, from the first guess of a single line (its coarse copies' shape when long).
  // Each solve's work is counted, a failed one's too.
  State SolveHeld(int i) {
    double work = 0;  // station-passes of this line's solves, its coarse copies' included
    LineEquilibriumOptions options = line_options_;
    options.work = &work;
    struct Counted {  // however the solves end
      HeldLines& lines;
      int i;
      const double& work;
      ~Counted() { lines.Count(i, work); }
    } counted{*this, i, work};
    if (states_[i].x.size() != 0) {
      options.warm_start = true;
      reports_[i] = LineEquilibriumReport{};
      try {
        return SolveLineEquilibrium(models_[i], MovedGuess(i), &reports_[i], options);
      } catch (const CancelledError&) {
        throw;
      } catch (const StaticsWorkError&) {
        throw;
      } catch (const Error&) {
        // from the first guess instead
      }
    }
    options.warm_start = false;
    reports_[i] = LineEquilibriumReport{};
    const bool specs = i < static_cast<int>(sys_.line_specs.size()) &&
                       i < static_cast<int>(sys_.line_prisms.size());
    if (!specs) return SolveLineEquilibrium(models_[i], &reports_[i], options);
    return SolveLongLineEquilibrium(
        models_[i],
        LineMaking{sys_.line_specs[i].sections, sys_.line_prisms[i], sys_.env, models_[i].line.law},
        &reports_[i], options);
  }
  void Count(int i, double work) {  // [station-passes]
    *work_ += work;
    line_work_[i] += work;
  }

  // The last equilibrium of line i with its held ends moved to their new positions, the
  // stations between shifted in proportion to their arc length.
  Points MovedGuess(int i) const {
    const LineModel& m = models_[i];
    Points x = states_[i].x;
    const int s = m.line.links;
    const Vec d0 = m.ends.start.prescribed() ? Vec(m.ends.start.rest() - x.col(0)) : Vec::Zero();
    const Vec d1 = m.ends.end.prescribed() ? Vec(m.ends.end.rest() - x.col(s)) : Vec::Zero();
    const double L = m.line.total_length();
    for (int j = 0; j <= s; ++j) {
      const double f = m.line.arc_length[j] / L;
      x.col(j) += (1.0 - f) * d0 + f * d1;
    }
    return x;
  }

  const Model& sys_;
  const Unknowns& u_;
  std::vector<LineModel>& models_;
  std::vector<Ends> ends_;  // models_' own, put back when it goes
  std::vector<State> states_;
  std::vector<LineEquilibriumReport> reports_;
  mutable std::vector<std::array<Vec, 2>> forces_;  // each line's end stations' (Force)
  std::vector<std::array<Vec, 2>> held_at_;          // where its state was solved (HeldAt)
  mutable std::vector<char> known_;                 // whether forces_ holds them
  LineEquilibriumOptions line_options_;
  std::vector<double> line_work_;  // each line's solves in this call [station-passes]
  double most_work_;  // station-passes (EquilibriumOptions::max_line_work)
  double own_work_ = 0;
  double* work_;      // where they are added up
};

}  // namespace

Points SharedPointResiduals(const Model& sys, const std::vector<State>& states) {
  Points R = Points::Zero(kDim, sys.shared_count());
  for (int p : sys.shared_points)
    for (const LineEnd& e : sys.points[p].ends)
      R.col(sys.points[p].shared) += StaticStationForce(sys.lines[e.line], states[e.line], e.station);
  return R;
}

Vec6 LinesLoadOnBody(const Model& sys, const std::vector<State>& states, int b,
                     const Vec6& pose) {
  return LinesLoad(sys, states, b, pose, [&](int i, int j) {
    return StaticStationForce(sys.lines[i], states[i], j);
  });
}

namespace {

// The unknowns' first guess and the lines held there (their warm starts): the points and
// bodies where the scene puts them, the joints of chains where the chains solved as one line
// put them; or where options.guess, a state of the lines, has them.
Eigen::VectorXd FirstGuess(const Model& sys, const Unknowns& u,
                           const EquilibriumOptions& options, HeldLines& lines,
                           int* chain_count) {
  Eigen::VectorXd X(u.size);
  for (const Unknowns::Group& g : u.groups) {
    if (g.body >= 0) {
      X.segment<6>(g.offset) = options.guess ? options.guess_poses[g.body] : sys.body_poses[g.body];
      continue;
    }
    const LineEnd& o = sys.owner(g.point);
    const LineModel& m = sys.lines[o.line];
    X.segment<kDim>(g.offset) = options.guess ? Vec((*options.guess)[o.line].x.col(o.station))
                                              : (o.station == 0 ? m.ends.start : m.ends.end).rest();
  }
  if (options.guess) {
    lines.Restore(*options.guess);
  } else {
    // Chains of lines through joints, each solved as one line: their joints where that puts
    // them, their lines' shapes the first guesses (chain_guess.h).
    double work = 0;  // the chains' solves, counted with the held lines'
    ChainGuess chains = GuessChains(sys, options.cancel, &work, options.max_line_statics);
    lines.AddWork(work);
    for (const Unknowns::Group& g : u.groups) {
      if (g.point < 0) continue;
      const int shared = sys.points[g.point].shared;
      if (chains.guessed[shared]) X.segment<kDim>(g.offset) = chains.shared_positions.col(shared);
    }
    lines.Restore(std::move(chains.states));
    *chain_count = chains.chains;
  }
  lines.Solve(X, HeldLines::kAll);
  return X;
}

}  // namespace

HeldFirstGuess HoldAtFirstGuess(const Model& sys, const EquilibriumOptions& options) {
  std::vector<LineModel> models = sys.lines;
  return HoldAtFirstGuessInPlace(sys, models, options);
}

HeldFirstGuess HoldAtFirstGuessInPlace(const Model& sys, std::vector<LineModel>& models,
                                       const EquilibriumOptions& options) {
  const Unknowns u(sys);
  HeldLines lines(sys, models, u, options);
  int chains = 0;
  const Eigen::VectorXd X = FirstGuess(sys, u, options, lines, &chains);
  HeldFirstGuess guess{lines.states(), sys.body_poses};
  for (const Unknowns::Group& g : u.groups)
    if (g.body >= 0) guess.body_poses[g.body] = X.segment<6>(g.offset);
  return guess;
}

std::vector<State> SolveCoupledEquilibrium(const Model& sys, EquilibriumReport* report,
                                          const EquilibriumOptions& options) {
  std::vector<LineModel> models = sys.lines;
  return SolveCoupledEquilibriumInPlace(sys, models, report, options);
}

std::vector<State> SolveCoupledEquilibriumInPlace(const Model& sys,
                                                  std::vector<LineModel>& models,
                                                  EquilibriumReport* report,
                                                  const EquilibriumOptions& options) {
  const Unknowns u(sys);
  const int n = u.size;
  // The lines' loads before their ends are held (a held end's chord would count).
  double scale = 0;
  for (const LineModel& m : sys.lines) scale += StaticForceScale(m);
  HeldLines lines(sys, models, u, options);
  int chain_count = 0;
  Eigen::VectorXd X = FirstGuess(sys, u, options, lines, &chain_count);
  EquilibriumReport r;
  r.force_scale = scale;
  r.chains = chain_count;
  Eigen::VectorXd R = lines.Residual(X);
  // The out-of-balance measure: forces [N], and a body's moments over its size [N].
  Eigen::VectorXd weight = Eigen::VectorXd::Ones(n);
  for (const Unknowns::Group& g : u.groups)
    if (g.body >= 0) weight.segment<3>(g.offset + 3).setConstant(1.0 / g.radius);
  auto norm = [&](const Eigen::VectorXd& v) {
    return v.size() ? v.cwiseProduct(weight).lpNorm<Eigen::Infinity>() : 0.0;
  };
  // Broyden's method: the Jacobian dR/dX by forward differences (a group at a time, each
  // column re-solving that group's lines) at the start and whenever a step fails to reduce the
  // out-of-balance load, and updated by rank one after each step that does (the held lines'
  // solves are the cost: one per step instead of one per unknown).
  Eigen::MatrixXd J(n, n);
  bool fresh = false;
  auto differences = [&] {
    const HeldLines::Kept base = lines.Keep();
    for (int k = 0; k < static_cast<int>(u.groups.size()); ++k) {
      const Unknowns::Group& g = u.groups[k];
      for (int c = 0; c < g.size; ++c) {
        // A millionth of its shortest line (a turn moves its farthest point as far).
        const double delta = 1e-6 * g.limit / (c < 3 ? 1.0 : g.radius);
        Eigen::VectorXd Xd = X;
        Xd[g.offset + c] += delta;
        lines.Solve(Xd, k);
        J.col(g.offset + c) = (lines.Residual(Xd) - R) / delta;
        lines.Restore(base);  // the lines at X again
      }
    }
    fresh = true;
  };
  // Balanced when each group's out-of-balance load is within the tolerance, or within what its
  // lines' round-off allows: the round-off their end forces carry, half of each line's floor
  // (LineEquilibriumReport::roundoff_floor, 4 eps |x| EA / l: a station's, between two links;
  // an end's force has one), summed over its ends. A chain of 10^6 links carries 0.37 N, six
  // hundred times the 6e-4 N asked of a clump between two such lines, and the Broyden steps
  // crawled there until they ran out of work. That up to kMostFloor of the lines' load: a
  // fuzzed file's chain of 20 links of 5 um carried 35 N, not a balance to accept (its
  // relaxation says so).
  auto balanced = [&](const Eigen::VectorXd& v) {
    const std::vector<LineEquilibriumReport>& held = lines.reports();
    for (const Unknowns::Group& g : u.groups) {
      double floor = 0;
      for (const Point& p : sys.points) {
        if (g.point >= 0 ? &p != &sys.points[g.point] : p.on_body != g.body) continue;
        for (const LineEnd& e : p.ends) floor += 0.5 * held[e.line].roundoff_floor;
      }
      const double out =
          v.segment(g.offset, g.size).cwiseProduct(weight.segment(g.offset, g.size))
              .lpNorm<Eigen::Infinity>();
      if (out > std::max(options.tolerance * scale, std::min(floor, kMostFloor * scale)))
        return false;
    }
    return true;
  };
  bool jacobian = false;  // made when first needed: none for a first guess already balanced
  double best = norm(R);  // the smallest out-of-balance load so far, and when it fell by 1 %
  int improved = 0;
  while (!balanced(R)) {
    if (!jacobian) {
      differences();
      jacobian = true;
    }
    if (norm(R) < 0.99 * best) best = norm(R), improved = r.iterations;
    const bool stalled =
        options.stall_iterations > 0 && r.iterations - improved >= options.stall_iterations;
    if (++r.iterations > options.max_iterations || stalled) {
      // Name the one most out of balance, and what usually causes it.
      const Unknowns::Group* worst = &u.groups.front();
      double worst_force = -1;
      for (const Unknowns::Group& g : u.groups) {
        const double f = R.segment(g.offset, g.size).cwiseProduct(weight.segment(g.offset, g.size))
                             .lpNorm<Eigen::Infinity>();
        if (f > worst_force) worst_force = f, worst = &g;
      }
      const bool body = worst->body >= 0;
      std::ostringstream os;
      os << "the shared points and free bodies of the system do not balance after "
         << r.iterations - 1 << " Newton iterations"
         << (stalled ? " (the last " + std::to_string(options.stall_iterations) +
                           " gained less than 1 %)"
                     : std::string())
         << ": out-of-balance force " << norm(R)
         << " N on " << (body ? "body " : "point ")
         << '"' << (body ? sys.bodies[worst->body].name : sys.points[worst->point].name) << '"'
         << " (the lines' own loads are " << scale << " N); a free "
         << (body ? "body's" : "point's") << " given position is only the first guess of its "
         << "equilibrium, which may not be reached from one far from it (a body or point given "
         << "above the anchor it hangs below, say): give one nearer where it comes to rest";
      throw Error(os.str());
    }
    ThrowIfCancelled(options.cancel, "the system's static equilibrium");
    if (options.solving)
      options.solving(std::min(1.0, std::max(double(r.iterations) / options.max_iterations,
                                             lines.work() / options.max_line_work)));
    // The least-squares step of least size: a direction nothing stiffens (a body's yaw on one
    // mooring point, its turns when its lines meet at its reference) stays where it is.
    Eigen::VectorXd dX = J.completeOrthogonalDecomposition().solve(-R);
    for (const Unknowns::Group& g : u.groups) {  // at most a tenth of the shortest line
      const double most = 0.1 * g.limit;
      const double size = dX.segment<kDim>(g.offset).norm();
      if (size > most) dX *= most / size;
      if (g.body < 0) continue;
      const double turn = dX.segment<3>(g.offset + 3).norm() * g.radius;
      if (turn > most) dX *= most / turn;
    }
    const HeldLines::Kept base = lines.Keep();
    lines.Solve(X + dX, HeldLines::kMoved);
    Eigen::VectorXd Rt = lines.Residual(X + dX);
    if (!(norm(Rt) < norm(R)) && !fresh) {  // an old Jacobian: a fresh one, and again
      lines.Restore(base);
      lines.Solve(X, HeldLines::kMoved);
      differences();
      --r.iterations;
      continue;
    }
    // Backtracking: the step halved until the out-of-balance load falls.
    double step = 1;
    for (int tries = 0; !(norm(Rt) < norm(R)) && tries < 12; ++tries) {
      lines.Restore(base);
      step *= 0.5;
      lines.Solve(X + step * dX, HeldLines::kMoved);
      Rt = lines.Residual(X + step * dX);
    }
    const Eigen::VectorXd s = step * dX;
    J += (Rt - R - J * s) * s.transpose() / s.squaredNorm();
    fresh = false;
    X += s;
    R = Rt;
  }
  r.residual = norm(R);
  r.line_work = lines.work();
  r.lines = lines.reports();
  r.body_poses = sys.body_poses;
  for (const Unknowns::Group& g : u.groups)
    if (g.body >= 0) r.body_poses[g.body] = X.segment<6>(g.offset);
  if (report) *report = r;
  return lines.states();
}

}  // namespace cablefilm
