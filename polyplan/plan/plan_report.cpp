#include <polyplan/plan/plan_report.hpp>

namespace polyplan {
std::string_view to_string(PlanStatus status) {
  switch (status) {
    case PlanStatus::solved: return "solved";
    case PlanStatus::no_path: return "no_path";
    case PlanStatus::not_found: return "not_found";
    case PlanStatus::limit: return "limit";
    case PlanStatus::invalid_query: return "invalid_query";
    case PlanStatus::local_minimum: return "local_minimum";
  }
  return "unknown";
}

const FactValue* Facts::value_named(std::string_view name) const {
  for (const auto& [key, value] : entries_)
    if (key == name) return &value;
  return nullptr;
}

void Facts::put(std::string_view name, FactValue value) {
  for (auto& [key, existing] : entries_)
    if (key == name) {
      existing = std::move(value);
      return;
    }
  entries_.emplace_back(std::string(name), std::move(value));
}

}  // namespace polyplan
