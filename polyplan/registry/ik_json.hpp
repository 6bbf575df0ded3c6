#pragma once
// The JSON document of an inverse-kinematics study (arm/ik_study.hpp), which `polyplan ik --json`
// prints and Python's polyplan.ik returns as a dict: {target, orientation, found, solutions
// [{angles, error, free}], why_not (when not found)}.
#include <polyplan/arm/ik_study.hpp>

#include <nlohmann/json_fwd.hpp>

namespace polyplan {

nlohmann::json ik_json(const IkRequest& request, const IkStudy& study);

}  // namespace polyplan
