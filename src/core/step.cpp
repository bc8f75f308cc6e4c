#include "core/step.h"

#include <string>

#include "core/cancel.h"
#include "core/coupled_explicit_step.h"
#include "core/coupled_step.h"
#include "core/explicit_step.h"
#include "core/implicit_step.h"
#include "core/inextensible_step.h"

namespace cablefilm {

void StepLine(const LineModel& m, LineData& d, const Inputs& in, double dt) {
  UpdateWater(m, in, d.state.t + 0.5 * dt, &d.water);
  switch (d.options.scheme) {
    case Scheme::kExplicit:
      return ExplicitStep(m, d, in, dt);
    case Scheme::kImplicit:
      return ImplicitStep(m, d, in, dt);
    case Scheme::kInextensible:
      return InextensibleStep(m, d, in, dt);
  }
}

void Step(const Model& m, Data& d, const Inputs& in, double dt) {
  const double t_end = d.t + dt;
  const bool name = m.lines.size() > 1;  // a line alone needs no name
  for (int k = 0; k < static_cast<int>(m.islands.size()); ++k) {
    const Island& isl = m.islands[k];
    if (!isl.coupled()) {
      const int i = isl.lines.front();
      try {
        StepLine(m.lines[i], d.lines[i], in, dt);
      } catch (const BlowUpError& e) {
        if (!name) throw;
        throw BlowUpError("line \"" + m.line_names[i] + "\": " + e.what(), e.time, e.station);
      }
      continue;
    }
    for (int i : isl.lines) UpdateWater(m.lines[i], in, d.t + 0.5 * dt, &d.lines[i].water);
    if (d.lines[isl.lines.front()].options.scheme == Scheme::kExplicit) {
      d.islands[k].t = d.t;
      StepCoupledExplicit(m, k, d, in, dt);
    } else {
      StepCoupledIsland(m, k, d, in, dt);
    }
    for (int i : isl.lines) {
      d.lines[i].state.t = t_end;
      try {
        CheckStateSane(m.lines[i], d.lines[i].state, d.lines[i].forces.geometry.length);
      } catch (const BlowUpError& e) {
        throw BlowUpError("line \"" + m.line_names[i] + "\": " + e.what(), e.time, e.station);
      }
    }
  }
  d.t = t_end;
  for (int k = 0; k < static_cast<int>(d.bodies.size()); ++k)
    if (!d.bodies[k].q.allFinite() || !d.bodies[k].v.allFinite())
      throw BlowUpError("body \"" + m.bodies[m.free_bodies[k]].name +
                            "\": its pose is not finite at t = " + std::to_string(d.t) + " s",
                        d.t, 0);
}

void StepSpan(const Model& m, Data& d, const Inputs& in, double seconds, int steps) {
  const double t0 = d.t, dt = seconds / steps;
  for (int k = 0; k < steps; ++k) {
    ThrowIfCancelled(in.stop, "the simulation");
    Step(m, d, in, dt);
  }
  d.t = t0 + seconds;
  for (LineData& line : d.lines) line.state.t = d.t;
}

}  // namespace cablefilm
