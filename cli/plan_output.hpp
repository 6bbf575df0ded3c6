#pragma once
// How a Plan is printed: DESIGN.md's JSON object, and a readable line for people.
#include <polyplan/roadmaps/plan.hpp>
#include <polyplan/geometry/world.hpp>

#include <nlohmann/json.hpp>

#include <ostream>

namespace polyplan::cli {

nlohmann::json plan_json(const Plan& plan);
void print_plan(std::ostream& out, const Query& query, const Plan& plan);

}  // namespace polyplan::cli
