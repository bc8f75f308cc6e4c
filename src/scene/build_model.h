#pragma once
// From the scene's plain data to the physics model (parse, then build).
#include "core/model.h"
#include "scene/scene_def.h"

namespace cablefilm {

// The scene's model: its lines, points and bodies ([cable] and [ends]: one line between two
// points). Throws Error naming the scene when it cannot be built (a free point no line holds,
// a line whose ends are both loose, an inextensible line joined to others).
Model BuildModel(const SceneDef& scene);

// An end's (a point's, a body's reference point's) motion as the scene gives it.
EndMotion MakeEndMotion(const EndDef& e);
// A driven body's angles in time [rad] about `rest_angles` [rad] (its orientation): the
// trochoid's or the table's angles; fixed at rest_angles when none of them moves.
EndMotion MakeTurnMotion(const EndDef& e, const Vec& rest_angles);

// What `check` and `run` say of the scene's table motions (ends, points, bodies), a line each
// in `notes` (file, rows, span, interpolation, speed at the first and last rows), and in
// `warnings` each table the run (to its last whole output.interval within simulation.duration)
// goes past while the table still moves at its last row: after it the end holds still, a jump
// in velocity no recorded motion has.
void DescribeTables(const SceneDef& scene, std::vector<std::string>* notes,
                    std::vector<std::string>* warnings);

// The scene's [waves] for the core (phase in rad); not present without the table.
WaveSpec MakeWaveSpec(const SceneDef& scene);

// The station a weight's arc length falls on (the loader has checked that it does).
int StationAt(const std::vector<SectionDef>& sections, double arc_length, const std::string& path);

}  // namespace cablefilm
