#include "core/force_jacobian.h"

#include <cmath>

#include "core/seabed_friction.h"
#include "core/wave_forces.h"

namespace cablefilm {
namespace {

// The optional parts of a link's derivative blocks (axial damping, tangential drag, a current
// profile's slope), built as matrices only where the model has them. Stored negated. Each
// matrix is read only where its flag is set, and left unset otherwise (27 stores a link saved
// on a line without them).
struct LinkExtras {
  Mat dd;       // added to the derivatives of both forces w.r.t. d = x_{k+1} - x_k
  Mat damping;  // the axial damping's, added to that of the force on k alone
  Mat dv;       // added to their derivative w.r.t. v_k (= w.r.t. v_{k+1})
  Vec slope_column = Vec::Zero();  // a current profile's: in the y column of all four blocks
  bool any_dd = false, any_damping = false, any_dv = false;
};

// Adds a link's four blocks to the rows of stations a = k and c = k + 1, entry by entry in
// scalars. With fa = -dF_a/dd (F_a the link's force on a, d = x_c - x_a), fc = -dF_c/dd and
// f_dv = -dF_a/dv_a (= the other three velocity derivatives: the drag sees the mean velocity):
//   -dF_a/dx_a = fa - kv f_dv,  -dF_a/dx_c = -fa - kv f_dv,
//   -dF_c/dx_a = fc - kv f_dv,  -dF_c/dx_c = -fc - kv f_dv.
// fa = (dT/dL - T/L) t t^T + (T/L) I (+ axial damping) + H, fc = -(the same before H) + H, with
// the normal drag's H = (f / 2L)((t . w) GP + s t q^T) and f_dv = -(f / 4) GP, GP = s I +
// q q^T / s - s t t^T. No matrix is formed: entries stored one by one and then read as a
// matrix stalled the processor's store forwarding (a third of this function's samples).
[[gnu::always_inline]] inline void AddLinkBlocks(
    const LineModel& m, int k, const Vec& t, double dTdL, double TL, double drag, double s,
    const Vec& q, double tw, double L, const LinkExtras& x, double kv, bool profile,
    BlockTridiagonal& system) {
  const int j0 = m.first_free(), j1 = m.last_free();
  const int a = k, c = k + 1;
  const bool free_a = a >= j0 && a <= j1, free_c = c >= j0 && c <= j1;
  const bool both = free_a && free_c;
  const bool normal_drag = drag != 0 && s > 0;
  // The drag factor f [kg/m] (force over |q| q) in H [kg/m^2] and in f_dv [kg/m].
  const double h = 0.5 * drag / L, e = -0.25 * drag;
  Mat* diag_a = free_a ? &system.diag[a - j0] : nullptr;
  Mat* diag_c = free_c ? &system.diag[c - j0] : nullptr;
  Mat* upper = both ? &system.upper[a - j0] : nullptr;
  Mat* lower = both ? &system.lower[c - j0] : nullptr;
  for (int col = 0; col < kDim; ++col) {
    for (int row = 0; row < kDim; ++row) {
      const double tt = t[row] * t[col], id = row == col ? 1.0 : 0.0;
      double fa = (dTdL - TL) * tt + TL * id;
      if (x.any_damping) fa += x.damping(row, col);
      double fc = -fa, f_dv = 0.0;
      if (normal_drag) {
        const double GP = (s * id + q[row] * (q[col] / s)) - s * tt;
        const double H = h * (tw * GP + (s * t[row]) * q[col]);
        fa += H;
        fc += H;
        f_dv = e * GP;
      }
      if (x.any_dd) fa += x.dd(row, col), fc += x.dd(row, col);
      if (x.any_dv) f_dv += x.dv(row, col);
      double v = kv * f_dv;
      if (profile && col == kVertical) v -= x.slope_column[row];
      if (free_a) (*diag_a)(row, col) += fa - v;
      if (both) (*upper)(row, col) += -fa - v;
      if (both) (*lower)(row, col) += fc - v;
      if (free_c) (*diag_c)(row, col) += -fc - v;
    }
  }
}

}  // namespace

void AddForceJacobian(const LineModel& m, const Water& water, const LinkGeometry& g,
                      const Eigen::VectorXd& tension, const Points& v, double kv,
                      BlockTridiagonal& system) {
  const bool profile = !m.env.current_profile.empty();
  const bool waves = UsesSea(m, g);  // then the drag is in AddWaveForceJacobian
  const int j0 = m.first_free(), j1 = m.last_free();
  auto free = [&](int j) { return j >= j0 && j <= j1; };
  Vec current = CurrentAt(m, water, 0.0);
  for (int k = 0; k < m.line.links; ++k) {
    const double L = g.length[k];
    if (!(L > 0)) continue;
    const Vec t = g.tangent.col(k);
    // Tension T t on station k, -T t on k+1: axial stiffness (taut only) and geometric T/L.
    // dT/dL = EA/l on a taut link, 0 on a slack one and on a taut one whose axial damping
    // (a link shortening fast) holds its tension at 0 (forces.cpp: T = max(0, EA e + c dL/dt)).
    const double dTdL =
        L > m.line.rest_length[k] && tension[k] > 0 ? m.line.axial_stiffness[k] / m.line.rest_length[k] : 0.0;
    const double TL = tension[k] / L;  // [N/m]
    LinkExtras x;
    // Axial damping c dL/dt t, dL/dt = t . (v_b - v_a), while it leaves the tension positive:
    // through v_b - v_a = kv d (the scheme's velocity follows the position) it adds kv c t t^T,
    // and through t it adds c t (P (v_b - v_a) / L)^T (the geometric part is in T/L above).
    if (m.line.axial_damping.size() != 0 && m.line.axial_damping[k] != 0 && dTdL > 0 && tension[k] > 0) {
      const double c = m.line.axial_damping[k];
      const Mat tt = t * t.transpose();
      const Vec dv = v.col(k + 1) - v.col(k);
      x.damping = c * (kv * tt + t * ((Mat::Identity() - tt) * dv / L).transpose());
      x.any_damping = true;
    }
    // Normal drag on both stations, -(f^D / 2) |q| q, q = P w the part across the link of the
    // relative velocity w = mean velocity - c: through the orientation (P) and the velocity.
    // Tangential drag, -(f^T / 2) |p| p t, p = t . w: likewise.
    const double f = m.line.drag_factor[k], ft = m.line.tangential_drag_factor[k];
    const bool drag = (f != 0 || ft != 0) && !waves;
    Vec q = Vec::Zero();
    double s = 0, tw = 0;
    if (drag) {
      const double ymid = profile ? 0.5 * (g.elevation[k] + g.elevation[k + 1]) : 0.0;
      if (profile) current = CurrentAt(m, water, ymid);
      const Vec w = 0.5 * (v.col(k) + v.col(k + 1)) - current;
      q = w - t * t.dot(w);
      // G = d(|q| q) / dq = |q| I + q q^T / |q|, and as q is across the link (q . t = 0),
      // G P = G - |q| t t^T and G t = |q| t: hence GP and H in AddLinkBlocks, with
      // dq/dd = -((t . w) P + t q^T) / L (NormalPartDerivative) and, through w = mean
      // velocity, dq/dv = P / 2.
      s = q.norm();
      tw = t.dot(w);
      const double p = tw;  // [m/s]
      if (ft != 0 && p != 0) {
        // d(|p| p t)/dd = |p| (2 t q^T + p P) / L (dt/dd = P / L, dp/dd = q^T / L, q = P w);
        // d/dv_k: through dp/dv = t^T / 2, d(|p| p)/dp = 2 |p|.
        const Mat tt = t * t.transpose();
        const double c = -0.5 * ft * std::abs(p);  // [kg/s]
        x.dd = (2.0 * c / L) * t * q.transpose() - (c * p / L) * tt + (c * p / L) * Mat::Identity();
        x.dv = c * tt;
        x.any_dd = x.any_dv = true;
      }
      // A current profile: w = mean velocity - c((y_k + y_{k+1})/2), so the force on either
      // station depends on y_k and y_{k+1} alike through dw/dy = -c'/2: dF/dy_i = 2 f_dv
      // (-c'/2) = -f_dv c'. Stored negated, in the y column of all four blocks, where
      // AddLinkBlocks subtracts it with kv f_dv.
      if (profile) {
        const Mat tt = t * t.transpose();
        Mat f_dv = Mat::Zero();
        if (f != 0 && s > 0) f_dv = (-0.25 * f) * (NormalDragDerivative(q) - s * tt);
        if (x.any_dv) f_dv += x.dv;
        x.slope_column = f_dv * CurrentSlope(m, water, ymid);
      }
    }
    AddLinkBlocks(m, k, t, dTdL, TL, drag ? f : 0.0, s, q, tw, L, x, kv, profile, system);
  }
  // Prism drag -u f (.) rel, rel = v_j - c(y_j) e_x: a function of the station's own velocity,
  // and of its elevation through a current profile.
  if (waves) AddWaveForceJacobian(m, water, g, v, kv, system);
  if ((kv != 0 || profile) && !waves) {
    for (int j : m.line.weight_stations) {
      if (!free(j)) continue;
      if (profile) current = CurrentAt(m, water, g.elevation[j]);
      const Vec rel = v.col(j) - current;
      const double u = rel.norm();
      if (u == 0) continue;
      const Vec f = m.line.prism_drag.col(j);
      const Mat dfdv = -(f.asDiagonal() * (u * Mat::Identity() + rel * rel.transpose() / u));
      system.diag[j - j0] -= kv * dfdv;
      // dF/dy_j = dfdv (-c'); stored negated in the y column.
      const Vec slope = profile ? CurrentSlope(m, water, g.elevation[j]) : Vec::Zero();
      if (!slope.isZero()) system.diag[j - j0].col(kVertical) += dfdv * slope;
    }
  }
  if (m.env.seabed.present) {
    // The seabed on station j below it (forces.cpp): N(p, v_y) with p = y_b - y_j, so
    // dN/dy = -dN/dp; friction F_h = -mu N g(v_h), g = tanh(|v_h| / v_f) v_h / |v_h|. Negated
    // derivatives:
    //   -dF_y/dy = dN/dp,  -dF_y/dv_y = -dN/dv_y,
    //   -dF_h/dy = -mu g dN/dp,  -dF_h/dv_y = mu g dN/dv_y,
    //   -dF_h/dv_h = mu N dg/dv_h,
    //   dg/dv_h = sech^2(s) / v_f e e^T + tanh(s) / |v_h| (I_h - e e^T),  e = v_h / |v_h|,
    //   s = |v_h| / v_f (1 / v_f I_h at rest), I_h the identity on the horizontal axes.
    // Stick-slip (seabed_friction.h): F_h = -K s - C v_h sticking, mu N u sliding;
    //   -dF_h/dx_h - kv dF_h/dv_h = scale (K + kv C) across,  -dF_h/d(y, v_y) as above with
    //   mu u in place of -mu g (sliding; nothing sticking).
    const SeabedSpec& bed = m.env.seabed;
    const bool sticks = HasStickSlip(m);
    for (int j = j0; j <= j1; ++j) {
      const double p = bed.y - g.elevation[j];
      if (!(p > 0)) continue;
      const SeabedReaction r = SeabedNormal(m, j, p, v(kVertical, j));
      if (!(r.N > 0)) continue;
      Mat B = Mat::Zero();
      B(kVertical, kVertical) = r.dN_dp - kv * r.dN_dvy;
      if (sticks && g.stick.cols() > 0) {
        const double K = m.line.friction_stiffness[j], C = m.line.friction_damping[j];
        const StickSlipForce f = StickSlipFriction(bed.friction, r.N, K, C, g.stick.col(j),
                                                   HorizontalPart(v.col(j)));
        if (f.sliding) B.col(kVertical) += f.force / r.N * B(kVertical, kVertical);
        B += (f.scale * (K + kv * C)) * f.across;
      } else if (bed.friction > 0 && !sticks) {
        const Vec gj = SlidingDirection(v.col(j), bed);
        B.col(kVertical) -= bed.friction * B(kVertical, kVertical) * gj;
        Mat I_h = Mat::Identity();
        I_h(kVertical, kVertical) = 0;
        const Vec vh = HorizontalPart(v.col(j));
        const double speed = vh.norm(), vf = bed.friction_velocity;
        Mat dg = I_h / vf;
        if (speed > 0) {
          const Vec e = vh / speed;
          const double th = FrictionShape(speed / vf), sech2 = 1.0 - th * th;
          dg = (sech2 / vf) * e * e.transpose() + (th / speed) * (I_h - e * e.transpose());
        }
        B += (kv * bed.friction * r.N) * dg;
      }
      system.diag[j - j0] += B;
    }
  }
}

void SetInertiaJacobian(const LineModel& m, const LinkGeometry& g, const Points& a,
                        double ka, BlockTridiagonal& system) {
  const int j0 = m.first_free(), j1 = m.last_free();
  // Each row's blocks cleared where its inertia is added (a separate pass over the 2 MB of a
  // long line's blocks cost 3 % of its run).
  for (int j = j0; j <= j1; ++j) {
    system.lower[j - j0].setZero();
    system.upper[j - j0].setZero();
    system.diag[j - j0].setZero();
    AddStationInertia(m, g, j, ka, system.diag[j - j0]);
  }
  // d/dd of (e/2) (I - t t^T) a_j for each station j of link k: (e/2) d(P a)/dd.
  // The tangential added mass e^t t t^T / 2 = e^t (I - P) / 2 has the same derivative with the
  // opposite sign: the two together are that of (e - e^t) P / 2.
  for (int k = 0; k < m.line.links; ++k) {
    const double en = m.line.virtual_mass[k], et = m.line.tangential_virtual_mass[k];
    if ((en == 0 && et == 0) || !(g.length[k] > 0)) continue;
    const Vec t = g.tangent.col(k);
    // With waves the added mass is that of the link's wet fraction (wave_forces.h).
    const double e = 0.5 * (en - et) * (UsesSea(m, g) ? LinkWet(g.sea, k) : 1.0);
    for (int j : {k, k + 1}) {
      if (j < j0 || j > j1) continue;
      // e dq/dd with q = P a_j: -(e / L)((t . a) P + t (P a)^T) = -(e / L)((t . a) I + t u^T),
      // u = a - 2 (t . a) t (NormalPartDerivative, written out).
      const Vec aj = a.col(j);
      const double ta = t.dot(aj), r = -e / g.length[k];
      const Vec rt = r * t, u = aj - (2 * ta) * t;
      // B += sign D, D = (r t) u^T + (r ta) I, entry by entry: D built as a matrix in memory
      // and read back whole stalled the store forwarding (a fifth of this function's time).
      auto add = [&](Mat& B, double sign) {
        for (int c = 0; c < kDim; ++c)
          for (int q = 0; q < kDim; ++q) B(q, c) += sign * (rt[q] * u[c] + (q == c ? r * ta : 0.0));
      };
      // d = x_{k+1} - x_k: +D with respect to x_{k+1}, -D with respect to x_k.
      if (k >= j0) add(j == k ? system.diag[j - j0] : system.lower[j - j0], -1.0);
      if (k + 1 <= j1) add(j == k ? system.upper[j - j0] : system.diag[j - j0], 1.0);
    }
  }
  if (UsesSea(m, g)) AddWaveInertiaJacobian(m, g, a, system);
}

}  // namespace cablefilm
