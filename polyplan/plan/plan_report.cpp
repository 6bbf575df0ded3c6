#include <polyplan/plan/plan_report.hpp>

#include <stdexcept>

namespace polyplan {
namespace {

template <class T>
const T& read(const Facts& facts, std::string_view name, const char* kind) {
  const FactValue* value = facts.find(name);
  if (!value) throw std::out_of_range("no fact \"" + std::string(name) + "\"");
  const T* typed = std::get_if<T>(value);
  if (!typed) throw std::out_of_range("the fact \"" + std::string(name) + "\" is not a " + kind);
  return *typed;
}

}  // namespace

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

const FactValue* Facts::find(std::string_view name) const {
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

std::int64_t Facts::count(std::string_view name) const { return read<std::int64_t>(*this, name, "count"); }

double Facts::number(std::string_view name) const {
  if (const FactValue* value = find(name))
    if (const auto* whole = std::get_if<std::int64_t>(value)) return static_cast<double>(*whole);
  return read<double>(*this, name, "number");
}

const std::string& Facts::text(std::string_view name) const { return read<std::string>(*this, name, "word"); }

bool Facts::flag(std::string_view name) const { return read<bool>(*this, name, "flag"); }

}  // namespace polyplan
