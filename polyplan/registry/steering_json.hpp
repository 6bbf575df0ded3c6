#pragma once
// The JSON document of a steering curve (car/steering_path.hpp), which `polyplan steer --json`
// prints and Python's polyplan.steer returns as a dict: {length, word, segments [{steer, gear,
// length}]}, and with --all-words every word tried.
#include <polyplan/car/steering_path.hpp>

#include <nlohmann/json_fwd.hpp>

#include <string>

namespace polyplan {

nlohmann::json steering_json(const SteeringPath& path);

// Every word tried (steer --all-words): [{name, length (null: infeasible), shortest}], the
// shortest one marked.
nlohmann::json steering_words_json(const SteeringWords& words);

// The same for people: a line a word, "  LSR  infeasible", "  LSL  12.3457  shortest".
std::string steering_words_text(const SteeringWords& words);

// The line people read: "dubins LSL: length 12.3457" ("(no motion)" for an empty word).
std::string steering_summary(const std::string& model, const SteeringPath& path);

}  // namespace polyplan
