// `polyplan benchmark`: the shipped experiments (data/experiments/) at a small scale, their outputs
// checked — the OMPL log read by the tests' own reader of the format, its runs and times those of
// results.json, the pictures SVG, a table row per planner entry — and bad experiment files.
#include "../experiment/ompl_log_parser.hpp"
#include "cli_runner.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>

namespace polyplan::test {
namespace {

namespace fs = std::filesystem;

struct Outputs {
  CliRun run;
  fs::path dir;
};

// Runs the shipped experiment `name` with two seeds and a short time limit into a fresh folder.
Outputs run_shipped(const std::string& name, const std::string& time_limit) {
  const fs::path dir =
      fs::temp_directory_path() / ("polyplan_benchmark_test_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(dir);
  const CliRun run =
      run_polyplan("benchmark '" + kSource + "/data/experiments/" + name + ".json' --seeds 2 --time-limit " +
                   time_limit + " --threads 2 --out '" + dir.string() + "'");
  return {run, dir};
}

bool python_can_parse_xml() { return std::system("python3 -c 'import xml.etree.ElementTree' >/dev/null 2>&1") == 0; }

void check_outputs(const Outputs& outputs, std::size_t problems, std::size_t entries, bool anytime) {
  ASSERT_EQ(outputs.run.exit_code, 0) << outputs.run.err;
  EXPECT_NE(outputs.run.err.find("runs: " + std::to_string(problems * entries * 2) + "/" +
                                 std::to_string(problems * entries * 2)),
            std::string::npos)
      << outputs.run.err;  // the progress bar
  const nlohmann::json results = nlohmann::json::parse(slurp(outputs.dir / "results.json"));
  const OmplLog log = read_ompl_log((outputs.dir / "results.log").string());

  // One planner per (problem, entry), each with a run per seed, in results.json's order.
  ASSERT_EQ(log.planners.size(), problems * entries);
  EXPECT_EQ(log.runs_per_planner, 2);
  ASSERT_EQ(results["runs"].size(), problems * entries * 2);
  std::size_t next = 0;
  for (const OmplLogPlanner& planner : log.planners) {
    ASSERT_EQ(planner.runs.size(), 2u) << planner.name;
    const auto column = [&](const std::string& name) {
      return static_cast<std::size_t>(std::find(planner.columns.begin(), planner.columns.end(), name) -
                                      planner.columns.begin());
    };
    for (const auto& values : planner.runs) {
      const nlohmann::json& run = results["runs"][next++];
      EXPECT_EQ(run["log_planner"].get<std::string>(), planner.name);
      EXPECT_EQ(std::stod(values.at(column("time"))), run["time"].get<double>());  // the same double
      EXPECT_EQ(values.at(column("solved")), run["solved"].get<bool>() ? "1" : "0");
      EXPECT_EQ(std::stoull(values.at(column("seed"))), run["seed"].get<std::uint64_t>());
    }
  }
  // results.csv: a header and a row per run.
  EXPECT_EQ(lines(slurp(outputs.dir / "results.csv")), 1 + problems * entries * 2);

  // tables.md: a table per problem, a row per planner entry in each.
  const std::string tables = slurp(outputs.dir / "tables.md");
  for (const auto& entry : results["experiment"]["planners"]) {
    std::size_t rows = 0;
    for (std::size_t at = tables.find("| " + entry["name"].get<std::string>() + " | "); at != std::string::npos;
         at = tables.find("| " + entry["name"].get<std::string>() + " | ", at + 1))
      ++rows;
    EXPECT_GE(rows, problems) << entry["name"];
  }

  // The pictures: per problem success, time and length, and cost for anytime planners; all read
  // as XML in one python3 call when python3 is there.
  std::string pictures;
  for (const auto& problem : results["experiment"]["problems"]) {
    std::vector<std::string> kinds{"success", "time", "length"};
    if (anytime) kinds.push_back("cost");
    for (const std::string& kind : kinds) {
      const fs::path svg = outputs.dir / (problem["name"].get<std::string>() + "-" + kind + ".svg");
      const std::string text = slurp(svg);
      ASSERT_EQ(text.rfind("<?xml", 0), 0u) << svg;
      EXPECT_NE(text.find("<svg"), std::string::npos) << svg;
      EXPECT_NE(text.find("</svg>"), std::string::npos) << svg;
      pictures += " '" + svg.string() + "'";
    }
  }
  if (python_can_parse_xml()) {  // braces: EXPECT_EQ is an if-else of its own
    EXPECT_EQ(std::system(
                  ("python3 -c 'import sys, xml.etree.ElementTree as E; [E.parse(f) for f in sys.argv[1:]]'" + pictures)
                      .c_str()),
              0)
        << "a picture is not well-formed XML:" << pictures;
  }
  fs::remove_all(outputs.dir);
}

TEST(BenchmarkCommand, Seed003RrtAndRrtStarAtASmallScale) {
  check_outputs(run_shipped("seed003_rrt_rrtstar", "0.2"), 2, 9, true);
}

TEST(BenchmarkCommand, Seed001KPrmAtASmallScale) { check_outputs(run_shipped("seed001_kprm", "2"), 2, 3, false); }

TEST(BenchmarkCommand, ABadExperimentFileExitsTwoNamingTheObject) {
  const fs::path file = fs::temp_directory_path() / ("polyplan_bad_experiment_" + std::to_string(::getpid()) + ".json");
  {
    std::ofstream out(file);
    out << R"({"problems": [{"name": "office", "file": ")" << kSource << R"(/data/worlds/office.json"}],
               "planners": [{"name": "a", "planner": "rrt"}, {"name": "b", "planner": "rrtstar", "options": {"kk": 3}}],
               "seeds": [1], "time_limit": 1})";
  }
  const CliRun run = run_polyplan("benchmark '" + file.string() + "'");
  fs::remove(file);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find(file.string() +
                         ": planners[1].options.kk: unknown option for rrtstar (options: rewire, k, goal-bias"),
            std::string::npos)
      << run.err;
  EXPECT_EQ(lines(run.err), 1u);
}

TEST(BenchmarkCommand, MoreSeedsThanTheExperimentHasIsBadInput) {
  const CliRun run =
      run_polyplan("benchmark '" + kSource + "/data/experiments/seed001_kprm.json' --seeds 11 --out /tmp/never");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("--seeds 11: the experiment has 10 seeds"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace polyplan::test
