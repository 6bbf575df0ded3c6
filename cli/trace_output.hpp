#pragma once
// --trace of search, plan and replan: one JSON line per expansion of a graph search, with the same
// keys whatever the command (docs/search_trace.md):
//   {"step": k, "vertex": V, "g": g, "h": h, "f": f, "backpointer": B or null, "open": n}
// V and B are how the command names a vertex (an index; a plan's index with "at": [x, y]; a
// replan's cell [x, y]); a command adds its own keys (a plan's "query", a replan's "replan").
// Keys keep that order (ordered_json); a command's own keys come after them.
#include <nlohmann/json.hpp>

#include <cstddef>
#include <fstream>
#include <optional>
#include <ostream>
#include <string>

namespace polyplan::cli {

nlohmann::ordered_json expansion_line(std::size_t step, nlohmann::ordered_json vertex, double g, double h, double f,
                                      nlohmann::ordered_json backpointer, std::size_t open);

// The search's ExpansionRecord with vertices as indices.
template <class Record>
nlohmann::ordered_json expansion_line(const Record& e) {
  return expansion_line(e.step, e.vertex, e.g, e.h, e.f,
                        e.backpointer ? nlohmann::ordered_json(*e.backpointer) : nlohmann::ordered_json(nullptr),
                        e.open);
}

// Where trace lines go: a file, or standard output for "-". Throws InputError naming the file when
// it cannot be opened or written.
class TraceOutput {
 public:
  explicit TraceOutput(const std::string& target);
  void line(const nlohmann::ordered_json& value);
  std::ostream& stream() { return *out_; }
  // Flushes and checks that everything was written.
  void finish();

 private:
  std::string target_;
  std::ofstream file_;
  std::ostream* out_;
};

}  // namespace polyplan::cli
