// polyplan replan MAP.map --start X,Y --goal X,Y --sensor R [--algorithm dstar-lite|lpastar|astar]
// [--json FILE|-] [--svg OUT.svg [--animate]] [--trace FILE|-] [--rhs-trace FILE|-]: a robot that discovers the
// MovingAI map as it drives (x = column, y = row), replanning with D* Lite, LPA* or A* from scratch.
// --trace writes one JSON line per expansion of every replan, with the keys of search's and plan's
// --trace; --rhs-trace (what --trace wrote before) the course's planning problem set's g/rhs tables for every pass.
#include "cli/command.hpp"
#include "cli/option_flags.hpp"
#include "cli/trace_output.hpp"

#include <polyplan/draw/replan_svg.hpp>
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/incremental/discovering_robot.hpp>
#include <polyplan/incremental/replan_options.hpp>
#include <polyplan/io/movingai_map.hpp>
#include <polyplan/registry/replan_json.hpp>

#include <charconv>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

namespace polyplan::cli {
namespace {

struct ReplanCommandOptions {
  std::string map, start, goal;
  std::unique_ptr<CommandOptions<ReplanOptions>> replanning;
  std::string json, svg, trace, rhs_trace;
  bool animate = false;
};

// "X,Y" with integers, each read whole and checked for overflow (sscanf's %d wraps 4294967336 to 40).
GridPoint cell_option(const std::string& text, const char* option) {
  const auto comma = text.find(',');
  const auto whole = [&](std::string_view part) -> std::optional<int> {
    int value = 0;
    const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), value);
    if (error != std::errc() || end != part.data() + part.size() || part.empty()) return std::nullopt;
    return value;
  };
  const std::string_view all(text);
  const auto x = comma == std::string::npos ? std::nullopt : whole(all.substr(0, comma));
  const auto y = comma == std::string::npos ? std::nullopt : whole(all.substr(comma + 1));
  if (!x || !y)
    throw InputError(std::string(option) + " " + text +
                     ": expected X,Y (a column and a row, whole numbers of the map)");
  return {*x, *y};
}

// Every pass of every replan as an expansion line (cli/trace_output.hpp): the popped cell, its g after
// the pass (null when raised to ∞), h, f = the key's first part (with D* Lite's k_m), the cell its
// rhs reads (the backpointer), the open list's size after the pass; then the replan's number and
// the pass's kind ("over", "under", "stale key").
class ExpansionTraceWriter : public ReplanTrace {
 public:
  explicit ExpansionTraceWriter(const std::string& target) : out_(target) {}
  void replan_begins(std::size_t, GridPoint, std::size_t) override {}
  void pass(const ReplanTracePass& p) override {
    const auto cell = [](GridPoint c) { return nlohmann::ordered_json::array({c.x, c.y}); };
    auto line = expansion_line(p.pass, cell(p.popped), p.g_after.to_double(), p.h.to_double(), p.key_first.to_double(),
                               p.backpointer ? cell(*p.backpointer) : nlohmann::ordered_json(nullptr), p.open.size());
    line["replan"] = p.replan;
    line["kind"] = p.kind;
    out_.line(line);
  }
  void finish() { out_.finish(); }

 private:
  TraceOutput out_;
};

// Both traces when both are asked for.
class BothTraces : public ReplanTrace {
 public:
  BothTraces(ReplanTrace& a, ReplanTrace& b) : a_(&a), b_(&b) {}
  void replan_begins(std::size_t replan, GridPoint at, std::size_t changed) override {
    a_->replan_begins(replan, at, changed);
    b_->replan_begins(replan, at, changed);
  }
  void pass(const ReplanTracePass& p) override {
    a_->pass(p);
    b_->pass(p);
  }

 private:
  ReplanTrace *a_, *b_;
};

// --rhs-trace: the course's planning problem set's g/rhs tables as JSON lines (one per replan's start, one per pass) or
// as the seed's tables.
class TraceWriter : public ReplanTrace {
 public:
  TraceWriter(std::ostream& out, bool tables) : out_(&out), tables_(tables) {}
  void replan_begins(std::size_t replan, GridPoint at, std::size_t changed) override {
    if (!tables_) {
      *out_ << replan_begins_json(replan, at, changed).dump() << '\n';
      return;
    }
    *out_ << "replan " << replan << " at " << cell(at) << ": " << changed << " cell(s) changed\n";
  }
  void pass(const ReplanTracePass& p) override {
    if (tables_) return print(p);
    *out_ << replan_pass_json(p).dump() << '\n';
  }

 private:
  static std::string cell(GridPoint p) { return "(" + std::to_string(p.x) + "," + std::to_string(p.y) + ")"; }
  static std::string number(const OctileLength& c) {
    if (c == OctileLength::infinity()) return "∞";
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", c.to_double());
    return text;
  }
  // Left-aligned in `width` characters, counted as code points ("∞" is one).
  static std::string pad(const std::string& text, std::size_t width) {
    std::size_t shown = 0;
    for (const unsigned char c : text) shown += (c & 0xC0) != 0x80;
    return text + std::string(width > shown ? width - shown : 0, ' ');
  }
  void row(const std::vector<std::string>& cells) {
    static constexpr std::size_t widths[] = {10, 9, 9, 20, 6};
    *out_ << "    ";
    for (std::size_t i = 0; i < cells.size(); ++i)
      *out_ << (i + 1 < cells.size() ? pad(cells[i], widths[i]) : cells[i]);
    *out_ << '\n';
  }
  void print(const ReplanTracePass& p) {
    *out_ << "  pass " << p.pass << ": pops " << cell(p.popped) << " key [" << number(p.key_first) << "; "
          << number(p.key_second) << "] (" << p.kind << "): g " << number(p.g_before) << " -> " << number(p.g_after)
          << ", rhs " << number(p.rhs) << '\n';
    if (!p.updated.empty()) {
      *out_ << "    updated rhs:\n";
      row({"cell", "g", "rhs", "list"});
      for (const auto& u : p.updated) row({cell(u.at), number(u.g), number(u.rhs), u.action});
    }
    *out_ << "    open list:\n";
    row({"cell", "g", "rhs", "key", "state"});
    for (const auto& e : p.open)
      row({cell(e.at), number(e.g), number(e.rhs), "[" + number(e.key_first) + "; " + number(e.key_second) + "]",
           e.state});
  }

  std::ostream* out_;
  bool tables_;
};

int run_replan(const ReplanCommandOptions& o) {
  ReplanOptions options = o.replanning->parse();
  if (o.animate && o.svg.empty()) throw InputError("--animate: give --svg OUT.svg for the animation");
  if ((o.json == "-") + (o.trace == "-") + (o.rhs_trace == "-") > 1)
    throw InputError("--json -, --trace - and --rhs-trace -: only one of them can go to standard output");
  const GridPoint start = cell_option(o.start, "--start"), goal = cell_option(o.goal, "--goal");
  GridMap map = read_movingai_map(o.map);

  std::ofstream trace_file;
  std::unique_ptr<TraceWriter> tables;
  if (o.rhs_trace == "-") {
    tables = std::make_unique<TraceWriter>(std::cout, true);
  } else if (!o.rhs_trace.empty()) {
    trace_file.open(o.rhs_trace);
    if (!trace_file) throw InputError(o.rhs_trace + ": cannot write the trace");
    tables = std::make_unique<TraceWriter>(trace_file, false);
  }
  std::unique_ptr<ExpansionTraceWriter> expansions;
  if (!o.trace.empty()) expansions = std::make_unique<ExpansionTraceWriter>(o.trace);
  std::unique_ptr<BothTraces> both;
  if (tables && expansions) both = std::make_unique<BothTraces>(*tables, *expansions);
  options.trace = both     ? static_cast<ReplanTrace*>(both.get())
                  : tables ? static_cast<ReplanTrace*>(tables.get())
                           : static_cast<ReplanTrace*>(expansions.get());
  const ReplanResult r = drive_through_unknown_map(std::move(map), start, goal, options);
  if (trace_file.is_open() && !trace_file.flush()) throw InputError(o.rhs_trace + ": cannot write the trace");
  if (expansions) expansions->finish();

  if (!o.json.empty()) write_json(replan_json(r, options.sensor_radius), o.json);
  if (!o.svg.empty())
    (o.animate ? draw_replan_animation(r, replan_title(r)) : draw_replan(r, replan_title(r))).write(o.svg);
  if (o.json != "-" && o.trace != "-" && o.rhs_trace != "-") {
    std::printf("%s: %s after %zu moves, cost %s (%.6g), %zu replans, %zu expanded, %.3g ms replanning\n",
                std::string(to_string(r.algorithm)).c_str(), std::string(to_string(r.status)).c_str(), r.moves,
                r.grid.text(r.traversed_cost).c_str(), r.grid.in_cells(r.traversed_cost), r.replans, r.expanded,
                r.seconds * 1e3);
  }
  return ok;
}

}  // namespace

void add_replan_command(CLI::App& app, Action& run) {
  auto options = std::make_shared<ReplanCommandOptions>();
  CLI::App* command =
      app.add_subcommand("replan", "Drive a robot through a MovingAI map it discovers as it goes, replanning");
  command->add_option("map", options->map, "MovingAI map (.map)")->required();
  command->add_option("--start", options->start, "Start cell X,Y (column, row)")->required();
  command->add_option("--goal", options->goal, "Goal cell X,Y (column, row)")->required();
  options->replanning = std::make_unique<CommandOptions<ReplanOptions>>(*command, replan_option_table());
  command->add_option("--json", options->json, "Write the drive as JSON to this file ('-' for standard output)");
  command->add_option("--svg", options->svg, "Draw the map, what the robot knew and its path (SVG)");
  command->add_flag("--animate", options->animate, "Make the --svg picture an animation, one frame per move");
  command->add_option(
      "--trace", options->trace,
      "Every expansion of every replan as a JSON line {step, vertex, g, h, f, backpointer, open, replan, kind} "
      "to this file ('-' for standard output), as search and plan write them. Changed: the course's planning problem "
      "set's g/rhs "
      "tables, which --trace wrote before, are now --rhs-trace");
  command->add_option("--rhs-trace", options->rhs_trace,
                      "The course's planning problem set's g/rhs tables for every pass of every replan: JSON lines to "
                      "this file, or tables with '-'");
  command->callback([options, &run] { run = [options] { return run_replan(*options); }; });
}

}  // namespace polyplan::cli
