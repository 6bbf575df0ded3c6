// polyplan plan PROBLEM.json [--planner NAME] [--option NAME=VALUE]... [--NAME VALUE]... [--query NAME]
//                            [--json FILE|-] [--svg OUT.svg] [--strobe OUT.svg [--every K]] [--trace FILE|-]
// The problem's queries (every one, or the one --query names) answered by one planner of the
// registry, built once through the front door (registry/any_planner.hpp): a world's, whatever its
// robot, or an arm's. `polyplan arm` is the same command under its old name.
#include "cli/command.hpp"
#include "cli/planner_choice.hpp"
#include "cli/trace_output.hpp"

#include <polyplan/draw/report_pictures.hpp>
#include <polyplan/geometry/input_error.hpp>

#include <cctype>
#include <iostream>

namespace polyplan::cli {
namespace {

struct PlanCommand {
  std::string file;
  std::string query;
  std::string json;
  std::string svg;
  std::string strobe;
  std::size_t every = 0;
  std::string trace;
  bool check_resolution = false;  // given: refused, since motions are certified, not sampled
  bool old_name = false;          // run as `polyplan arm`
  std::unique_ptr<PlannerChoice> planner;
};

// Every expansion of each query's graph search, as JSON lines: the vertex's index in the graph the
// planner searched, and where it is ("at"). Planners that search no graph record none.
void write_trace(const std::string& target, const std::vector<Report>& reports) {
  TraceOutput trace(target);
  std::size_t lines = 0;
  for (const Report& report : reports)
    for (const TracedExpansion& e : report.trace()) {
      auto line = expansion_line(e);
      line["at"] = e.at;
      line["query"] = report.query();
      trace.line(line);
      ++lines;
    }
  trace.finish();
  if (lines == 0 && !reports.empty())
    std::cerr << "warning: --trace: " << reports.front().planner()
              << " ran no graph search for these queries (the roadmap and raster planners record one)\n";
}

// OUT.svg for a picture of every query; OUT-NAME.svg for each query's own.
std::string picture_path(const std::string& base, const Picture& picture, std::size_t pictures) {
  if (pictures == 1) return base;
  std::string name;
  for (char c : picture.query) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  const auto dot = base.rfind(".svg");
  return (dot == std::string::npos ? base : base.substr(0, dot)) + "-" + name + ".svg";
}

void write_pictures(const Problem& problem, const std::vector<Report>& reports, const std::string& base,
                    PictureOptions options) {
  std::vector<const Report*> drawn;
  for (const Report& r : reports) drawn.push_back(&r);
  const std::vector<Picture> pictures = draw_reports(problem, drawn, options);
  try {
    for (const Picture& p : pictures) p.drawing.write(picture_path(base, p, pictures.size()));
  } catch (const std::runtime_error& e) {  // a picture that cannot be written
    throw InputError(e.what());
  }
}

// The problem's queries that --query asks for (all when it names none).
std::vector<std::size_t> asked_queries(const Problem& problem, const std::string& named) {
  const std::vector<std::string> names = problem.query_names();
  std::vector<std::size_t> asked;
  for (std::size_t i = 0; i < names.size(); ++i)
    if (named.empty() || names[i] == named) asked.push_back(i);
  if (!named.empty() && asked.empty()) throw InputError(problem.source() + ": no query named " + named);
  return asked;
}

int run_plan(const PlanCommand& command) {
  if (command.check_resolution)
    throw InputError(
        "--check-resolution is gone: every motion is certified free (conservative advancement), not "
        "sampled at a resolution; leave the option out");
  if (command.json == "-" && command.trace == "-")
    throw InputError("--json - and --trace -: only one of them can go to standard output");
  std::vector<std::string> warnings;
  const Problem problem = Problem::read(command.file, &warnings);
  print_warnings(warnings);
  command.planner->choose_for(problem);  // a bad planner or option is reported before any planning
  const auto planner = command.planner->make(problem);
  planner->require_plannable();
  const std::vector<std::size_t> asked = asked_queries(problem, command.query);

  QueryOptions query_options;
  query_options.record = !command.svg.empty() || !command.strobe.empty();  // the pictures show roadmaps and searches
  query_options.trace = !command.trace.empty();
  std::vector<Report> reports;
  for (std::size_t q : asked) reports.push_back(planner->plan(q, query_options));

  if (!command.trace.empty()) write_trace(command.trace, reports);
  const std::string settings = command.planner->settings();
  if (!command.svg.empty()) write_pictures(problem, reports, command.svg, {false, 0, settings});
  if (!command.strobe.empty()) write_pictures(problem, reports, command.strobe, {true, command.every, settings});
  if (!command.json.empty()) {
    nlohmann::json answers = nlohmann::json::array();
    for (const Report& r : reports) answers.push_back(r.to_json());
    write_json(answers.size() == 1 ? answers[0] : answers, command.json);
  }
  if (command.json != "-" && command.trace != "-") {
    for (const Report& r : reports) std::cout << r.summary() << '\n';
    if (!command.svg.empty()) std::cout << "picture: " << command.svg << '\n';
  }
  // After the answers, so that a mistake stays one line.
  if (command.old_name)
    std::cerr << "note: polyplan arm is polyplan plan now (the same options; --method is --planner)\n";
  return ok;
}

// The command under `name`: `plan`, or `arm`, its old name.
void add_command(CLI::App& app, Action& run, const std::string& name, const std::string& help, bool old_name) {
  auto command = std::make_shared<PlanCommand>();
  command->old_name = old_name;
  CLI::App* plan = app.add_subcommand(name, help);
  plan->add_option("problem", command->file, "World or arm file (JSON)")->required();
  plan->add_option("--query", command->query, "plan only the query with this name (e.g. easy)");
  plan->add_option("--json", command->json, "Write the plan(s) as JSON to this file ('-' for standard output)");
  plan->add_option(
      "--svg", command->svg,
      "Draw the plan(s): a world with its C-obstacles, the planner's roadmap or cells and the paths; an arm's "
      "motion as an animation (OUT-QUERY.svg for each of several queries)");
  plan->add_option("--strobe", command->strobe, "An arm: draw every k-th configuration of the motion at once");
  plan->add_option("--every", command->every, "k for --strobe (default: about 12 configurations)");
  plan->add_option(
      "--trace", command->trace,
      "Graph planners: every expansion of the search as a JSON line {step, vertex, g, h, f, backpointer, open, "
      "at, query} to this file ('-' for standard output)");
  // An option that would do nothing is refused, not ignored: a script that passes it learns why.
  plan->add_option_function<double>(
          "--check-resolution", [command](double) { command->check_resolution = true; },
          "refused: motions are certified, not sampled")
      ->group("");
  command->planner =
      std::make_unique<PlannerChoice>(*plan, "--planner", std::vector<std::string>{"--roadmap", "--method"});
  // The arm grid's evaluation as the flags older scripts use.
  auto* lazy = command->planner->add_alias(*plan, "--lazy", "evaluation", "lazy",
                                           "evaluation=lazy: decide cells when the search reaches them (default)");
  command->planner
      ->add_alias(*plan, "--eager", "evaluation", "eager", "evaluation=eager: evaluate every cell before searching")
      ->excludes(lazy);
  plan->callback([command, &run] { run = [command] { return run_plan(*command); }; });
}

}  // namespace

void add_plan_command(CLI::App& app, Action& run) {
  add_command(app, run, "plan",
              "Paths for the queries of a world or an arm from one planner (polyplan planners lists them)", false);
}

void add_arm_command(CLI::App& app, Action& run) {
  add_command(app, run, "arm", "The old name of plan (polyplan plan ARM.json works the same)", true);
}

}  // namespace polyplan::cli
