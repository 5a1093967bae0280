#pragma once
// Moving AI benchmark problems (a .scen file's lines, envs/moving_ai_scenario.h) as planning
// scenarios.

#include <string>

#include "planning/scenario.h"

namespace acdplan::planning {

/// Whether `path` names a Moving AI scenario file (extension `.scen`, any case).
bool IsMovingAiScenarioFile(const std::string& path);

/// The scenario of problem `problem` (its line among the file's problems, counted from 0) of
/// the Moving AI scenario file `path`: its map (envs::LoadMovingAiMap(), unit cells) as the
/// world, a point robot from the centre of the start cell to the centre of the goal cell
/// (envs::MovingAiCellCentre()), everything else at the scenario defaults. The description
/// names the problem, its bucket and its optimal length on the grid (8-connected, which an
/// any-angle path may beat).
/// @throws InputError: the file's errors (envs::ReadMovingAiScenario()), the map's, "<path>:
///         problem K out of range 0..N-1", "<path>:<line>: the map <map> has W x H cells, the
///         problem says W' x H'", "<path>:<line>: the start (goal) cell (x, y) is blocked".
Scenario ScenarioFromMovingAi(const std::string& path, int problem);

}  // namespace acdplan::planning
