#include "core/force_jacobian.h"

#include <cmath>

#include "core/wave_forces.h"

namespace cablefilm {
namespace {

// Adds the 2x2 derivative blocks of a link's force pair to the rows of stations a = k, b = k+1.
// dfa_dd, dfb_dd: derivatives w.r.t. d = x_b - x_a of the forces on a and b; dfa_dv, dfb_dv:
// derivatives w.r.t. v_a and v_b (equal, through the link's mean velocity). Stored negated.
struct LinkBlocks {
  Mat fa_dd = Mat::Zero(), fb_dd = Mat::Zero();
  Mat f_dv = Mat::Zero();  // same for both stations and both velocities
};

void Scatter(const Model& m, int k, const LinkBlocks& b, double kv, BlockTridiagonal& s) {
  const int j0 = m.first_free(), j1 = m.last_free();
  const int a = k, c = k + 1;
  const bool fa = a >= j0 && a <= j1, fc = c >= j0 && c <= j1;
  // -dF_a/dx_a = dfa_dd - kv f_dv, -dF_a/dx_c = -dfa_dd - kv f_dv, and likewise for c.
  if (fa) s.diag[a - j0] += b.fa_dd - kv * b.f_dv;
  if (fa && fc) s.upper[a - j0] += -b.fa_dd - kv * b.f_dv;
  if (fa && fc) s.lower[c - j0] += b.fb_dd - kv * b.f_dv;
  if (fc) s.diag[c - j0] += -b.fb_dd - kv * b.f_dv;
}

}  // namespace

void AddForceJacobian(const Model& m, const Water& water, const LinkGeometry& g,
                      const Eigen::VectorXd& tension, const Points& v, double kv,
                      BlockTridiagonal& system) {
  const bool profile = !m.env.current_profile.empty();
  const bool waves = m.has_waves();  // then the drag is in AddWaveForceJacobian
  const int j0 = m.first_free(), j1 = m.last_free();
  auto free = [&](int j) { return j >= j0 && j <= j1; };
  Vec current(CurrentAt(m, water, 0.0), 0.0);
  for (int k = 0; k < m.line.links; ++k) {
    const double L = g.length[k];
    if (!(L > 0)) continue;
    const Vec t = g.tangent.col(k);
    const Mat tt = t * t.transpose();
    LinkBlocks b;
    // Tension T t on station k, -T t on k+1: axial stiffness (taut only) and geometric T/L.
    // dT/dL = EA/l on a taut link, 0 on a slack one and on a taut one whose axial damping
    // (a link shortening fast) holds its tension at 0 (forces.cpp: T = max(0, EA e + c dL/dt)).
    const double dTdL =
        L > m.line.rest_length[k] && tension[k] > 0 ? m.line.axial_stiffness[k] / m.line.rest_length[k] : 0.0;
    const Mat G =
        dTdL * tt + (tension[k] / L) * (Mat::Identity() - tt);
    b.fa_dd = G;
    // Axial damping c dL/dt t, dL/dt = t . (v_b - v_a), while it leaves the tension positive:
    // through v_b - v_a = kv d (the scheme's velocity follows the position) it adds kv c t t^T,
    // and through t it adds c t (P (v_b - v_a) / L)^T (the geometric part is in T/L above).
    if (m.line.axial_damping.size() != 0 && m.line.axial_damping[k] != 0 && dTdL > 0 && tension[k] > 0) {
      const double c = m.line.axial_damping[k];
      const Vec dv = v.col(k + 1) - v.col(k);
      b.fa_dd += c * (kv * tt + t * ((Mat::Identity() - tt) * dv / L).transpose());
    }
    b.fb_dd = -b.fa_dd;
    // Normal drag D n / 2 on both stations, D = -f^D q |q|, q = n . (mean velocity - c).
    if (m.line.drag_factor[k] != 0 && !waves) {
      const Vec n(-t.y(), t.x());
      const Mat dn = NormalDerivative(t, L);
      const double ymid = profile ? 0.5 * (g.elevation[k] + g.elevation[k + 1]) : 0.0;
      if (profile) current.x() = CurrentAt(m, water, ymid);
      const Vec w = 0.5 * (v.col(k) + v.col(k + 1)) - current;
      const double q = w.dot(n);
      const double f = m.line.drag_factor[k];
      const Mat H =
          -0.5 * f * (2.0 * std::abs(q) * n * (w.transpose() * dn) + q * std::abs(q) * dn);
      b.fa_dd += H;
      b.fb_dd += H;
      b.f_dv = -0.5 * f * std::abs(q) * n * n.transpose();  // d(Dn/2)/dv_k, = d/dv_{k+1}
      // A current profile: w = mean velocity - c((y_k + y_{k+1})/2) e_x, so the force on
      // either station depends on y_k and y_{k+1} alike through dw/dy = -c'/2 e_x:
      // d(Dn/2)/dy_i = 2 f_dv (-c'/2 e_x) = -c' f_dv e_x. Stored negated, in the y column.
      const double slope = profile ? CurrentSlope(m, water, ymid) : 0.0;
      if (slope != 0) {
        Mat C = Mat::Zero();
        C.col(1) = slope * b.f_dv.col(0);
        const int a = k, c = k + 1;
        if (free(a)) system.diag[a - j0] += C;
        if (free(a) && free(c)) system.upper[a - j0] += C;
        if (free(a) && free(c)) system.lower[c - j0] += C;
        if (free(c)) system.diag[c - j0] += C;
      }
    }
    Scatter(m, k, b, kv, system);
  }
  // Prism drag -u f (.) rel, rel = v_j - c(y_j) e_x: a function of the station's own velocity,
  // and of its elevation through a current profile.
  if (waves) AddWaveForceJacobian(m, water, g, v, kv, system);
  if ((kv != 0 || profile) && !waves) {
    for (int j : m.line.weight_stations) {
      if (!free(j)) continue;
      if (profile) current.x() = CurrentAt(m, water, g.elevation[j]);
      const Vec rel = v.col(j) - current;
      const double u = rel.norm();
      if (u == 0) continue;
      const Vec f = m.line.prism_drag.col(j);
      const Mat dfdv =
          -(f.asDiagonal() * (u * Mat::Identity() + rel * rel.transpose() / u));
      system.diag[j - j0] -= kv * dfdv;
      // dF/dy_j = dfdv (-c' e_x); stored negated in the y column.
      const double slope = profile ? CurrentSlope(m, water, g.elevation[j]) : 0.0;
      if (slope != 0) system.diag[j - j0].col(1) += slope * dfdv.col(0);
    }
  }
  if (m.env.seabed.present) {
    // The seabed on station j below it (forces.cpp): N(p, v_y) with p = y_b - y_j, so
    // dN/dy = -dN/dp; friction F_x = -mu N tanh(u), u = v_x / v_f. Negated derivatives:
    //   -dF_y/dy = dN/dp,  -dF_y/dv_y = -dN/dv_y,
    //   -dF_x/dy = -mu tanh(u) dN/dp,  -dF_x/dv_y = mu tanh(u) dN/dv_y,
    //   -dF_x/dv_x = mu N sech^2(u) / v_f.
    const SeabedSpec& bed = m.env.seabed;
    for (int j = j0; j <= j1; ++j) {
      const double p = bed.y - g.elevation[j];
      if (!(p > 0)) continue;
      const SeabedReaction r = SeabedNormal(m, j, p, v(1, j));
      if (!(r.N > 0)) continue;
      Mat B = Mat::Zero();
      B(1, 1) = r.dN_dp - kv * r.dN_dvy;
      if (bed.friction > 0) {
        const double u = v(0, j) / bed.friction_velocity;
        const double th = FrictionShape(u), sech2 = 1.0 - th * th;
        B(0, 1) = -bed.friction * th * B(1, 1);
        B(0, 0) = kv * bed.friction * r.N * sech2 / bed.friction_velocity;
      }
      system.diag[j - j0] += B;
    }
  }
}

void AddInertiaJacobian(const Model& m, const LinkGeometry& g, const Points& a,
                        double ka, BlockTridiagonal& system) {
  const int j0 = m.first_free(), j1 = m.last_free();
  for (int j = j0; j <= j1; ++j) system.diag[j - j0] += ka * StationInertia(m, g, j);
  // d/dd of (e/2) n n^T a_j for each station j of link k: (e/2)[(n.a) dn + n (a^T dn)].
  for (int k = 0; k < m.line.links; ++k) {
    if (m.line.virtual_mass[k] == 0 || !(g.length[k] > 0)) continue;
    const Vec t = g.tangent.col(k);
    const Vec n(-t.y(), t.x());
    const Mat dn = NormalDerivative(t, g.length[k]);
    // With waves the added mass is that of the link's wet fraction (wave_forces.h).
    const double e = 0.5 * m.line.virtual_mass[k] *
                     (m.has_waves() ? 0.5 * (g.sea.wet[k] + g.sea.wet[k + 1]) : 1.0);
    for (int j : {k, k + 1}) {
      if (j < j0 || j > j1) continue;
      const Vec aj = a.col(j);
      const Mat D = e * (n.dot(aj) * dn + n * (aj.transpose() * dn));
      // d = x_{k+1} - x_k: +D with respect to x_{k+1}, -D with respect to x_k.
      if (k >= j0) (j == k ? system.diag[j - j0] : system.lower[j - j0]) -= D;
      if (k + 1 <= j1) (j == k ? system.upper[j - j0] : system.diag[j - j0]) += D;
    }
  }
  if (m.has_waves()) AddWaveInertiaJacobian(m, g, a, system);
}

}  // namespace cablefilm
