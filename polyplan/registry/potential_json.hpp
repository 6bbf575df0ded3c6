#pragma once
// The JSON document of a potential's critical points (reactive/potential_study.hpp), which
// `polyplan potential --json` prints and Python's polyplan.potential returns as a dict:
// {goal, parameters {zeta, d_star, eta, q_star}, box, cells_per_axis, candidates,
//  critical_points [{at, kind, eigenvalues, value, gradient}]}.
#include <polyplan/reactive/potential_study.hpp>

#include <nlohmann/json_fwd.hpp>

namespace polyplan {

nlohmann::json potential_json(const PotentialStudy& study);

}  // namespace polyplan
