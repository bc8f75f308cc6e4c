// Rigid bodies of a mooring system (issue 20): a free body in the statics and in the coupled
// step (coupled_equilibrium.h, coupled_step.h), and the quasi-static tools (body_statics.h). The
// truths: a free point (the system's shared station, checked in coupled_island_test.cpp against one
// line with a weight), the exact elastic catenary with a grounded part (test_support.h), and
// the tools' own offset-restoring curve.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "core/body_statics.h"
#include "core/error.h"
#include "core/equilibrium.h"
#include "core/coupled_step.h"
#include "test_support.h"

namespace cablefilm {
namespace {

using testing::Chain;
using testing::Figure;


constexpr double kRho = 1025, kG = 9.80665;


EnvironmentSpec Water(double current) {
  EnvironmentSpec env;
  env.fluid_density = kRho;
  env.gravity = kG;
  env.current = current;
  env.current_direction = Horizontal(0.6);
  return env;
}

// ---------------------------------------------------------------------------------------------
// Anchor -> 60 m -> junction -> 45 m -> a fairlead on a ship: the junction a free point, or a
// free body whose one point (where both lines end) is its reference point. The body's mass,
// buoyancy and added mass are the point's; with no arm, nothing turns it, so it moves as the
// point does.
const Vec kAnchor(0.0, -60.0, 0.0), kFairlead(70.0, 0.0, 10.0), kJunction(40.0, -45.0, 5.0);
const double kMass = 3000, kVolume = 0.4;
const Vec kAddedVolume(0.2, 0.3, 0.2);

EndMotion Ship() {
  return EndMotion::Trochoid(kFairlead, Vec(1.5, 0.8, 0.5), Vec(0.0, 0.6, -0.4),
                             2 * M_PI / 8.0, 0.5);
}

std::vector<LineSpec> TwoLines() {
  std::vector<LineSpec> lines(2);
  lines[0].name = "lower";
  lines[0].sections = {Chain(60, 24)};
  lines[0].start_point = 0;
  lines[0].end_point = 1;
  lines[1].name = "upper";
  lines[1].sections = {Chain(45, 18)};
  lines[1].start_point = 1;
  lines[1].end_point = 2;
  return lines;
}

Model JunctionAsPoint() {
  PrismSpec p;
  p.mass = kMass;
  p.volume = kVolume;
  p.added_volume = kAddedVolume;
  std::vector<PointSpec> points(3);
  points[0] = {"anchor", EndMotion::Fixed(kAnchor), {}};
  points[1] = {"junction", EndMotion::Free(kJunction), p};
  points[2] = {"fairlead", Ship(), {}};
  return MakeModel(TwoLines(), points, Water(0.4));
}

Model JunctionAsBody() {
  BodySpec b;
  b.name = "float";
  b.kind = BodyKind::kFree;
  b.motion = EndMotion::Free(kJunction);
  b.mass = kMass;
  b.volume = kVolume;
  b.inertia = Vec(50.0, 60.0, 70.0);
  b.added_mass << kRho * kAddedVolume, 0.0, 0.0, 0.0;
  std::vector<PointSpec> points(3);
  points[0] = {"anchor", EndMotion::Fixed(kAnchor), {}};
  points[1] = {"junction", EndMotion::Fixed(Vec::Zero()), {}, 0, Vec::Zero()};
  points[2] = {"fairlead", Ship(), {}};
  return MakeModel(TwoLines(), points, Water(0.4), {b});
}

double Gap(const Data& a, const Data& b) {
  double gap = 0;
  for (int i = 0; i < 2; ++i)
    gap = std::max(gap, (a.lines[i].state.x - b.lines[i].state.x).cwiseAbs().maxCoeff());
  return gap;
}

TEST(FreeBody, AtItsReferencePointItIsAFreePoint) {
  const Model point = JunctionAsPoint(), body = JunctionAsBody();
  ASSERT_EQ(body.free_bodies.size(), 1u);
  EquilibriumReport report;
  const std::vector<State> rest_point = SolveEquilibrium(point);
  const std::vector<State> rest_body = SolveEquilibrium(body, &report);
  // Statics: both balance the same forces to 1e-9 of the load (~60 kN), a position error of
  // that over the lines' stiffness across the junction (~1e4 N/m): ~6e-9 m.
  double gap = 0;
  for (int i = 0; i < 2; ++i)
    gap = std::max(gap, (rest_point[i].x - rest_body[i].x).cwiseAbs().maxCoeff());
  RecordProperty("statics_gap", Figure(gap));
  EXPECT_LT(gap, 1e-7);
  EXPECT_LT((report.body_poses[0].head<3>() - rest_point[0].x.col(24)).norm(), 1e-7);

  Model placed = body;
  PlaceBody(placed, 0, report.body_poses[0]);
  StepOptions o;
  o.scheme = Scheme::kImplicit;
  o.tolerance = 1e-4;
  const Inputs in = SceneInputs(point.lines[0]);
  Data a = MakeData(point, in, o, rest_point);
  Data b = MakeData(placed, in, o, rest_body);
  double worst = 0, travel = 0;
  for (int k = 0; k < 150; ++k) {  // 15 s: the ship's ramp and a period and more
    Step(point, a, in, 0.1);
    Step(placed, b, in, 0.1);
    worst = std::max(worst, Gap(a, b));
    travel = std::max(travel, (a.lines[0].state.x.col(24) - rest_point[0].x.col(24)).norm());
  }
  // The same equations through two paths (the shared station's 3 unknowns; the body's 6, of
  // which the turns are idle): they differ by Newton's tolerance (1e-9 of a link, 2.5e-9 m, per
  // step) and round-off, far below the step's error (1e-4 m); the junction moves metres.
  RecordProperty("dynamics_gap", Figure(worst));
  EXPECT_GT(travel, 0.3);
  EXPECT_LT(worst, 1e-6);
  EXPECT_EQ(ModelStepStats(point, a).steps, ModelStepStats(placed, b).steps);
  EXPECT_LT(b.bodies[0].q.tail<3>().norm(), 1e-9);  // nothing turns it
}

// The same junction stepped by the explicit scheme (coupled_explicit_step.h): a point's
// acceleration from the sum of its lines' rows, a body's from its mass matrix and its
// stations' forces through T, the same equations again; at its reference point the body's
// turns are idle, so both paths give the same motion to round-off.
TEST(FreeBody, ExplicitAtItsReferencePointItIsAFreePoint) {
  const Model point = JunctionAsPoint(), body = JunctionAsBody();
  EquilibriumReport report;
  const std::vector<State> rest_point = SolveEquilibrium(point);
  const std::vector<State> rest_body = SolveEquilibrium(body, &report);
  Model placed = body;
  PlaceBody(placed, 0, report.body_poses[0]);
  StepOptions o;
  o.scheme = Scheme::kExplicit;
  o.safety_factor = 0.8;  // automatic substeps below the stability limit
  const Inputs in = SceneInputs(point.lines[0]);
  Data a = MakeData(point, in, o, rest_point);
  Data b = MakeData(placed, in, o, rest_body);
  double worst = 0, travel = 0;
  for (int k = 0; k < 100; ++k) {  // 10 s: the ship's ramp and a period
    Step(point, a, in, 0.1);
    Step(placed, b, in, 0.1);
    worst = std::max(worst, Gap(a, b));
    travel = std::max(travel, (a.lines[0].state.x.col(24) - rest_point[0].x.col(24)).norm());
  }
  // The statics' gap (1e-7 m: Newton's tolerance on two paths) carried by the motion; the
  // junction moves metres.
  RecordProperty("dynamics_gap", Figure(worst));
  EXPECT_GT(travel, 0.3);
  EXPECT_LT(worst, 1e-6);
  EXPECT_EQ(ModelStepStats(point, a).steps, ModelStepStats(placed, b).steps);
  EXPECT_LT(b.bodies[0].q.tail<3>().norm(), 1e-9);  // nothing turns it
}

// The explicit and the implicit scheme on the junction as a body: two schemes of second order,
// one with its steps below the stability limit, the other's adaptive at 1e-5 m: they agree to
// the implicit steps' error, far below the junction's motion (metres).
TEST(FreeBody, ExplicitAgreesWithImplicitOnABody) {
  const Model body = JunctionAsBody();
  EquilibriumReport report;
  const std::vector<State> rest = SolveEquilibrium(body, &report);
  Model placed = body;
  PlaceBody(placed, 0, report.body_poses[0]);
  StepOptions e, i;
  e.scheme = Scheme::kExplicit;
  e.safety_factor = 0.8;
  i.scheme = Scheme::kImplicit;
  i.tolerance = 1e-5;
  const Inputs in = SceneInputs(placed.lines[0]);
  Data a = MakeData(placed, in, e, rest), b = MakeData(placed, in, i, rest);
  double worst = 0, pose = 0;
  for (int k = 0; k < 100; ++k) {
    Step(placed, a, in, 0.1);
    Step(placed, b, in, 0.1);
    worst = std::max(worst, Gap(a, b));
    pose = std::max(pose, (a.bodies[0].q - b.bodies[0].q).head<3>().norm());
  }
  RecordProperty("gap", Figure(worst));
  // Measured 2e-3 m over 10 s of a junction moving metres; 1 cm bounds the implicit steps'
  // error (1e-5 m a step over some 150 steps, the explicit one's O(h^2) far below it).
  EXPECT_LT(worst, 1e-2);
  EXPECT_LT(pose, 1e-2);
}

// ---------------------------------------------------------------------------------------------
// A platform on three identical chain legs, 120 degrees apart, each partly on a frictionless
// seabed in 100 m of water, its fairleads 20 m from its centre and 10 m below the surface.
struct Platform {
  double length = 500, radius = 20, anchor_radius = 470, depth = 100, draft = 10;
  int links = 50;
  double w() const {  // the chain's net weight per metre [N/m]
    const SectionSpec c = Chain(1, 1);
    return (c.mass_per_length - kRho * c.area) * kG;
  }
  double EA() const { return Chain(1, 1).youngs_modulus * Chain(1, 1).area; }
  // The legs' horizontal span, anchor to fairlead, with the platform centred [m].
  double span() const { return anchor_radius - radius; }
  double heading(int i) const { return 2 * M_PI * i / 3.0; }
  BodySpec Body(BodyKind kind) const {
    BodySpec b;
    b.name = "platform";
    b.kind = kind;
    b.motion = kind == BodyKind::kFree ? EndMotion::Free(Vec::Zero()) : EndMotion::Fixed(Vec::Zero());
    b.mass = 1e7;
    b.volume = b.mass / kRho;
    // Stiff in heave, roll and pitch (a waterplane of 1 km^2): the offset along x is the
    // moorings' alone.
    b.waterplane_area = 1e6;
    b.waterplane_inertia_x = b.waterplane_inertia_z = 1e11;
    return b;
  }
  // `current`: a surface current [m/s], uniform 5 m down and falling linearly to none at 20 m
  // (the grounded chain on a frictionless bed in a current would slide: no statics).
  Model System(BodyKind kind, const Vec& force = Vec::Zero(), double current = 0) const {
    EnvironmentSpec env = Water(0.0);
    if (current != 0) env.current_profile = {{-20.0, -5.0, 0.0}, {0.0, current, current}};
    env.seabed.present = true;
    env.seabed.y = -depth;
    env.seabed.stiffness = 3e7;
    BodySpec b = Body(kind);
    b.force = force;
    std::vector<PointSpec> points;
    std::vector<LineSpec> lines(3);
    for (int i = 0; i < 3; ++i) {
      const Vec e = Horizontal(heading(i));
      points.push_back({"anchor" + std::to_string(i),
                        EndMotion::Fixed(anchor_radius * e + Vec(0.0, -depth, 0.0)), {}});
      points.push_back({"fairlead" + std::to_string(i), EndMotion::Fixed(Vec::Zero()), {}, 0,
                        radius * e + Vec(0.0, -draft, 0.0)});
      lines[i].name = "leg" + std::to_string(i);
      lines[i].sections = {Chain(length, links)};
      lines[i].start_point = 2 * i;
      lines[i].end_point = 2 * i + 1;
    }
    return MakeModel(lines, points, env, {b});
  }
};

TEST(BodyStatics, CentredPlatformLegsAreTheGroundedCatenary) {
  const Platform p;
  const Model sys = p.System(BodyKind::kHeld);
  const MooringLoad load = LoadAtPose(sys, 0, Vec6::Zero());
  const testing::GroundedCatenary exact =
      testing::SolveGroundedCatenary(p.length, p.w(), p.EA(), p.span(), p.depth - p.draft);
  // Each leg's fairlead load against the closed form's fairlead tension: the lumped line is
  // second order in its link (seabed_test.cpp measures that convergence on a like case); at
  // 10 m links it is within 2e-3 (measured 7.8e-4).
  for (int i = 0; i < 3; ++i) {
    RecordProperty("fairlead_" + std::to_string(i),
                   Figure(load.end_tension[i] / exact.fairlead_tension() - 1));
    EXPECT_NEAR(load.end_tension[i], exact.fairlead_tension(), 2e-3 * exact.fairlead_tension());
  }
  // The three legs' pulls cancel horizontally at the centre (to the solves' 1e-9 of the load).
  const double H = exact.H;
  EXPECT_LT(HorizontalPart(load.load.head<3>()).norm(), 1e-6 * H);
}

TEST(BodyStatics, SurgeStiffnessIsTheCatenaryDerivative) {
  // Three legs at 0, 120, 240 degrees: K_xx = sum_i [H'(X) cos^2 + (H / X) sin^2] =
  // 1.5 (H' + H / X) with X the span (a leg's horizontal pull H(X) along it, turned as the
  // fairlead moves across it). H' by central differences of the closed form.
  const Platform p;
  const double h = p.depth - p.draft, dX = 0.5;
  auto H = [&](double X) { return testing::SolveGroundedCatenary(p.length, p.w(), p.EA(), X, h).H; };
  const double H0 = H(p.span());
  const double dH = (H(p.span() + dX) - H(p.span() - dX)) / (2 * dX);
  const double exact = 1.5 * (dH + H0 / p.span());
  double K[2];
  int k = 0;
  for (int links : {50, 100}) {
    Platform q = p;
    q.links = links;
    // Steps of a link's length: the lumped line's touchdown moves station by station, so its
    // H(X) is smooth only over a link; over one it follows the continuous curve.
    const Mat6 stiffness =
        MooringStiffness(q.System(BodyKind::kHeld), 0, Vec6::Zero(), p.length / links);
    K[k++] = stiffness(0, 0);
  }
  RecordProperty("K_exact", Figure(exact));
  RecordProperty("K_50", Figure(K[0]));
  RecordProperty("K_100", Figure(K[1]));
  // Second order in the link: the error at 100 links a quarter of that at 50 (measured 6.5 %
  // and 1.5 %; the next term and the touchdown's station-by-station walk make the ratio
  // 3 to 5.5), and within 2 % at 100 links.
  const double ratio = (K[0] - exact) / (K[1] - exact);
  RecordProperty("error_ratio", Figure(ratio));
  EXPECT_GT(ratio, 3.0);
  EXPECT_LT(ratio, 5.5);
  EXPECT_NEAR(K[1], exact, 0.02 * exact);
}

TEST(BodyStatics, FreeBodyUnderASteadyForceSitsOnTheOffsetCurve) {
  const Platform p;
  const Model free = p.System(BodyKind::kFree);
  const Vec6 rest = EquilibriumPose(free, 0);
  const double offset = 8.0;  // [m]
  const std::vector<OffsetPoint> curve = OffsetCurve(free, 0, rest, 0.0, {0.0, offset});
  // The curve starts at the balance: no restoring force at no offset.
  EXPECT_LT(std::abs(curve[0].restoring), 1e-6 * curve[1].restoring);
  // The body pushed by the curve's restoring force at `offset` comes to rest there: the
  // statics' residual (1e-9 of ~1.5e6 N) over the surge stiffness (~1e4 N/m) is 1e-7 m; the
  // heave and pitch the force brings (~3e5 N over the waterplane's 1e10 N/m: 3e-5 m) move the
  // surge force by K_xy 3e-5 m, a few newtons: 1e-4 m at most (measured 1.3e-8 m).
  const Model pushed = p.System(BodyKind::kFree, Vec(curve[1].restoring, 0.0, 0.0));
  const Vec6 pose = EquilibriumPose(pushed, 0);
  RecordProperty("offset_error", Figure(pose[0] - rest[0] - offset));
  EXPECT_NEAR(pose[0] - rest[0], offset, 1e-4);
  EXPECT_NEAR(pose[2], rest[2], 1e-6);  // symmetric about x: no sway
  EXPECT_GT(curve[1].restoring, 1e4);   // a real load: the legs' pull changes by a tenth
}

// The offset curve's heading is in degrees, a turn at most either way: 1e308 degrees (from
// Python) gave NaN loads. Every front end gets the refusal from here, naming the heading.
TEST(BodyStatics, OffsetCurveTakesHeadingsWithinATurn) {
  const Platform p;
  const Model held = p.System(BodyKind::kHeld);
  for (double heading : std::vector<double>{1e308, -1e308, -360.5, NAN, INFINITY}) {
    try {
      OffsetCurve(held, 0, Vec6::Zero(), heading, {1.0});
      ADD_FAILURE() << "heading " << heading << " taken";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("heading: expected an angle from -360 to 360 degrees"),
                std::string::npos)
          << e.what();
    }
  }
  // A whole turn either way is no turn; a quarter turn is +z.
  const double along_x = OffsetCurve(held, 0, Vec6::Zero(), 0.0, {1.0})[0].restoring;
  EXPECT_GT(along_x, 0.0);
  for (double turn : {360.0, -360.0})
    EXPECT_NEAR(OffsetCurve(held, 0, Vec6::Zero(), turn, {1.0})[0].restoring, along_x,
                1e-6 * along_x);
  const std::vector<OffsetPoint> along_z = OffsetCurve(held, 0, Vec6::Zero(), 90.0, {1.0});
  EXPECT_LT(along_z[0].load.load[2], 0.0);  // pulled back towards -z
  EXPECT_GT(along_z[0].restoring, 0.0);
}

// The platform in a surface current along Horizontal(0.6) with a quadratic damping in x and z
// (a drag 0.5 rho CdA: CdA 80 m^2), pushed at rest in the flow by B_2 |c_k| c_k on each axis.
constexpr double kCurrent = 0.5;  // [m/s]
constexpr double kDrag = 4.1e4;    // B_2 [N s^2/m^2]
Model DraggedPlatform(const Platform& p) {
  Model sys = p.System(BodyKind::kFree, Vec::Zero(), kCurrent);
  sys.bodies[0].quadratic_damping << kDrag, 0, kDrag, 0, 0, 0;
  return sys;
}

TEST(BodyStatics, CurrentDragOnTheBodyIsASteadyForceAlongTheFlow) {
  // A body held still in a current c (at its reference point) takes its drag B_2 |c_k| c_k
  // per axis (MoorDyn's body drag, on the water's velocity relative to it): the same pose as
  // the body without drag under that force as a constant one. The legs see the same current.
  const Platform p;
  const Model dragged = DraggedPlatform(p);
  const Vec flow = kCurrent * Horizontal(0.6);
  const Vec force = kDrag * flow.cwiseAbs().cwiseProduct(flow);  // per axis, as MoorDyn's
  const Vec6 pose = EquilibriumPose(dragged, 0);
  const Vec6 pushed = EquilibriumPose(p.System(BodyKind::kFree, force, kCurrent), 0);
  const Vec6 still = EquilibriumPose(p.System(BodyKind::kFree, Vec::Zero(), kCurrent), 0);
  RecordProperty("offset_by_drag", Figure(HorizontalPart((pose - still).head<3>()).norm()));
  // Both solves stop at 1e-9 of the load (~1e6 N) over a stiffness of ~1e4 N/m: 1e-7 m; the
  // bound ten times that. The drag moves the body by metres (measured 3.2 m).
  EXPECT_LT((pose - pushed).head<3>().norm(), 1e-6);
  EXPECT_LT((pose - pushed).tail<3>().norm(), 1e-8);
  EXPECT_GT(HorizontalPart((pose - still).head<3>()).norm(), 1.0);
}

TEST(FreeBody, InACurrentItSettlesWhereTheStaticsPutIt) {
  // Let go from its equilibrium in still water, with the current on: it drifts downstream and
  // settles at the equilibrium in the current (a linear damping near critical in surge and
  // sway, B_1 = 2 sqrt(K M)). Were the drag on its own velocity, it would stay where it
  // started: the current would not push it.
  const Platform p;
  Model sys = DraggedPlatform(p);
  BodySpec& b = sys.bodies[0];
  b.inertia = Vec(2e9, 3e9, 2e9);
  b.added_mass << 5e6, 1e7, 5e6, 4e8, 4e8, 4e8;
  const Vec6 target = EquilibriumPose(sys, 0);
  const Vec6 start = EquilibriumPose(p.System(BodyKind::kFree), 0);
  const double K = MooringStiffness(sys, 0, target, 1.0)(0, 0);
  const double M = b.mass + b.added_mass[0];
  b.linear_damping << 2 * std::sqrt(K * M), 0, 2 * std::sqrt(K * M), 0, 0, 0;
  const std::vector<State> lines = LoadAtPose(sys, 0, start).states;
  PlaceBody(sys, 0, start);
  StepOptions o;
  o.scheme = Scheme::kImplicit;
  o.tolerance = 5e-4;
  const Inputs in = SceneInputs(sys.lines[0]);
  Data sd = MakeData(sys, in, o, lines);
  const double period = 2 * M_PI * std::sqrt(M / K);  // the undamped surge period
  while (sd.t < 8 * period) Step(sys, sd, in, period / 8);
  const double drift = HorizontalPart((target - start).head<3>()).norm();
  const double left = HorizontalPart((target - sd.bodies[0].q).head<3>()).norm();
  RecordProperty("drift", Figure(drift));
  RecordProperty("left", Figure(left / drift));
  // Critically damped, after 8 periods (50 radians of omega t) what is left of the drift is
  // (1 + omega t) e^{-omega t} ~ 1e-20 of it, and the sway-surge coupling and the quadratic
  // part only speed it: the bound is the steps' and Newton's (the position tolerance 5e-4 m
  // a step, far below 1e-3 of a 3 m drift).
  EXPECT_LT(left, 1e-3 * drift);
  EXPECT_GT(drift, 1.0);
}

TEST(FreeBody, RollDecayHasTheHydrostaticPeriod) {
  // The platform rolled by 2 degrees and let go: it rolls at omega^2 = (C + K) / (I + A), the
  // waterplane's restoring C = rho g I_wp and the moorings' K = K_44 (their stiffness, from the
  // statics), about the reference point where its centre of gravity is.
  const Platform p;
  Model sys = p.System(BodyKind::kFree);
  BodySpec& b = sys.bodies[0];
  b.inertia = Vec(2e9, 3e9, 2e9);
  b.added_mass << 5e6, 1e7, 5e6, 4e8, 4e8, 4e8;
  b.waterplane_inertia_x = 1e5;  // C = 1.0e9 N m/rad in roll
  const Vec6 rest = EquilibriumPose(sys, 0);
  const double K44 = MooringStiffness(sys, 0, rest, 0.05)(3, 3);
  const double C44 = kRho * kG * b.waterplane_inertia_x;
  const double period = 2 * M_PI * std::sqrt((b.inertia[0] + b.added_mass[3]) / (C44 + K44));
  Vec6 start = rest;
  start[3] += 2 * M_PI / 180;
  const std::vector<State> lines = LoadAtPose(sys, 0, start).states;
  PlaceBody(sys, 0, start);
  StepOptions o;
  o.scheme = Scheme::kImplicit;
  o.tolerance = 5e-4;  // the default's scale: 1e-6 of the 500 m legs
  const Inputs in = SceneInputs(sys.lines[0]);
  Data sd = MakeData(sys, in, o, lines);
  const double dt = 0.02;
  std::vector<double> crossings;  // where the roll passes its rest angle going up
  double before = sd.bodies[0].q[3] - rest[3];
  for (int k = 1; sd.t < 3.2 * period; ++k) {
    Step(sys, sd, in, dt);
    const double now = sd.bodies[0].q[3] - rest[3];
    if (before < 0 && now >= 0) crossings.push_back(sd.t - dt * now / (now - before));
    before = now;
  }
  ASSERT_GE(crossings.size(), 3u);
  const double measured = (crossings.back() - crossings.front()) / (crossings.size() - 1);
  RecordProperty("period", Figure(period));
  RecordProperty("period_error", Figure(measured / period - 1));
  // The step's period error ((omega h)^2 / 12 at the steps the position tolerance allows, about
  // 0.1 s: 4e-4) and the lines' inertia at the fairleads (half a link's mass at 20 m: 1e-4 of
  // I) are below 2e-3; the linear crossing between rows of 0.02 s errs by (omega dt)^2 / 8 of
  // the row, 1e-6 of the period.
  EXPECT_NEAR(measured / period, 1.0, 2e-3);
  EXPECT_GT(K44 / C44, 1e-3);  // the moorings take part
}

TEST(FreeBody, RefusesToMoveWithoutInertia) {
  Platform p;
  Model sys = p.System(BodyKind::kFree);
  const std::vector<State> rest = SolveEquilibrium(sys);
  StepOptions o;
  o.scheme = Scheme::kImplicit;
  // No moments of inertia: its turns have no mass to step.
  EXPECT_THROW(MakeData(sys, SceneInputs(sys.lines[0]), o, rest), Error);
}

}  // namespace
}  // namespace cablefilm
