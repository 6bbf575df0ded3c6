#include "cli/trace_output.hpp"

#include <polyplan/geometry/input_error.hpp>

#include <cmath>
#include <iostream>

namespace polyplan::cli {

nlohmann::ordered_json expansion_line(std::size_t step, nlohmann::ordered_json vertex, double g, double h, double f,
                                      nlohmann::ordered_json backpointer, std::size_t open) {
  // An infinite value (a replan's vertex raised to ∞) is null, as JSON has no infinity.
  const auto value = [](double x) {
    return std::isfinite(x) ? nlohmann::ordered_json(x) : nlohmann::ordered_json(nullptr);
  };
  nlohmann::ordered_json line;
  line["step"] = step;
  line["vertex"] = std::move(vertex);
  line["g"] = value(g);
  line["h"] = value(h);
  line["f"] = value(f);
  line["backpointer"] = std::move(backpointer);
  line["open"] = open;
  return line;
}

TraceOutput::TraceOutput(const std::string& target) : target_(target), out_(&std::cout) {
  if (target == "-") return;
  file_.open(target);
  if (!file_) throw InputError(target + ": cannot write the trace");
  out_ = &file_;
}

void TraceOutput::line(const nlohmann::ordered_json& value) { *out_ << value.dump() << '\n'; }

void TraceOutput::finish() {
  if (!out_->flush())
    throw InputError((target_ == "-" ? std::string("standard output") : target_) + ": cannot write the trace");
}

}  // namespace polyplan::cli
