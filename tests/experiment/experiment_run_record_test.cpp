// A run's record (what a cluster's worker sends back, what runs.jsonl keeps) reads back to the same
// run bit for bit — every kind of fact in its order, infinite and NaN measures, doubles written to
// their last bit — refuses what is not a record naming the field, and an interrupted experiment's
// runs are written as such: in cell order, the missing ones counted.
#include <polyplan/experiment/experiment_file.hpp>
#include <polyplan/experiment/experiment_results.hpp>
#include <polyplan/experiment/experiment_run_record.hpp>
#include <polyplan/experiment/experiment_tables.hpp>
#include <polyplan/experiment/ompl_benchmark_log.hpp>
#include <polyplan/geometry/input_error.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>
#include <sstream>
#include <tuple>
#include <vector>

namespace polyplan {
namespace {

using nlohmann::json;

const std::string kRecordsFolderFile = std::string(POLYPLAN_SOURCE_DIR) + "/data/experiments/test.json";

Experiment two_by_two() {
  return parse_experiment(R"({"name": "records",
      "problems": [{"name": "office", "file": "../worlds/office.json"},
                   {"name": "maze", "file": "../worlds/maze.json"}],
      "planners": [{"name": "rrt", "planner": "rrt"}, {"name": "connect", "planner": "rrtconnect"}],
      "seeds": [7, 3], "time_limit": 5})",
                          kRecordsFolderFile);
}

ExperimentRun every_kind_of_fact() {
  ExperimentRun run;
  run.problem = 1;
  run.planner = 0;
  run.seed = 3;
  run.status = PlanStatus::solved;
  run.solved = true;
  run.seconds = 0.1 + 0.2;  // 0.30000000000000004: its last bit must come back
  run.setup_seconds = 1e-7;
  run.length = 3.0;
  run.improvements = {{0.01, 5.5}, {0.3, 3.0}};
  run.facts.set(FactKey<std::int64_t>{"samples"}, 412);
  run.facts.set(FactKey<double>{"bound"}, std::numeric_limits<double>::infinity());
  run.facts.set(FactKey<double>{"gap"}, std::nan(""));
  run.facts.set(FactKey<double>{"whole"}, 3.0);  // a measure that looks like a count stays a measure
  run.facts.set(FactKey<bool>{"roadmap.lazy"}, true);
  run.facts.set(FactKey<std::string>{"stopped_by"}, "solution");
  run.facts.set(FactKey<FactPoint>{"stop"}, FactPoint{1.5, -2});
  run.facts.set(FactKey<FactPoints>{"hits"}, FactPoints{{0, 1}, {2, 3}});
  run.facts.set(FactKey<FactCell>{"cell"}, FactCell{4, 5});
  return run;
}

TEST(ExperimentRunRecord, ReadsBackTheSameRunThroughText) {
  const Experiment e = two_by_two();
  const ExperimentRun run = every_kind_of_fact();
  const json text = json::parse(run_record(run, "maze", "rrt").dump());
  const ExperimentRun back = run_from_record(e, text, "runs.jsonl: line 2");
  EXPECT_EQ(back.problem, 1u);
  EXPECT_EQ(back.planner, 0u);
  EXPECT_EQ(back.seed, 3u);
  EXPECT_EQ(back.status, PlanStatus::solved);
  EXPECT_TRUE(back.solved);
  EXPECT_EQ(back.seconds, run.seconds);
  EXPECT_EQ(back.setup_seconds, run.setup_seconds);
  EXPECT_EQ(back.length, 3.0);
  ASSERT_EQ(back.improvements.size(), 2u);
  EXPECT_EQ(back.improvements[0].seconds, 0.01);
  ASSERT_EQ(back.facts.entries().size(), run.facts.entries().size());
  for (std::size_t i = 0; i < run.facts.entries().size(); ++i) {
    const auto& [name, value] = run.facts.entries()[i];
    EXPECT_EQ(back.facts.entries()[i].first, name);  // in order
    EXPECT_EQ(back.facts.entries()[i].second.index(), value.index()) << name;
    if (name != "gap") {
      EXPECT_EQ(back.facts.entries()[i].second, value) << name;
    }
  }
  EXPECT_TRUE(std::isnan(back.facts.at(FactKey<double>{"gap"})));
  EXPECT_EQ(text["facts"][1], json::array({"bound", "measure", "inf"}));
}

TEST(ExperimentRunRecord, RefusesWhatIsNotARecordNamingTheField) {
  const Experiment e = two_by_two();
  const json good = run_record(every_kind_of_fact(), "maze", "rrt");
  const auto refused = [&](const std::string& field, const json& value, const std::string& message) {
    json bad = good;
    if (value.is_discarded()) {
      bad.erase(field);
    } else {
      bad[field] = value;
    }
    try {
      run_from_record(e, bad, "runs.jsonl: line 4");
      ADD_FAILURE() << field << " accepted";
    } catch (const InputError& error) {
      EXPECT_EQ(std::string(error.what()), "runs.jsonl: line 4: " + message);
    }
  };
  refused("problem", "forest", "problem: \"forest\" is not one of the experiment's");
  refused("planner", 3, "planner: expected text");
  refused("seed", 4, "seed: 4 is not one of the experiment's seeds");
  refused("seed", -1, "seed: expected a whole number >= 0");
  refused("status", "lost", "status: \"lost\" is not a status");
  refused("seconds", "soon", "seconds: expected a number");
  refused("why_not", json(json::value_t::discarded), "why_not: missing");
  refused("facts", json::array({json::array({"samples", "count", 1.5})}), "facts.samples: expected a count, got 1.5");
  refused("facts", json::array({json::array({"x", "colour", 1})}), "facts.x: expected a colour, got 1");
  refused("improvements", json::array({json::array({1})}), "improvements: expected a point [x, y]");
}

TEST(ExperimentRunRecord, AnInterruptedExperimentIsWrittenAsSuch) {
  const Experiment e = two_by_two();
  std::vector<ExperimentRun> runs;
  const std::vector<std::tuple<int, int, int>> cells{{1, 1, 3}, {0, 0, 3}, {0, 0, 7}, {1, 1, 3}};
  for (const auto& [problem, planner, seed] : cells) {
    ExperimentRun run = every_kind_of_fact();
    run.problem = static_cast<std::size_t>(problem);
    run.planner = static_cast<std::size_t>(planner);
    run.seed = static_cast<std::uint64_t>(seed);
    runs.push_back(run);
  }
  runs[3].length = 99;  // a second record of one cell: the first is kept
  const ExperimentResults results{runs_in_cell_order(e, runs), 1.0, 2, "2026-12-07T10:00:00", "host"};
  ASSERT_EQ(results.runs.size(), 3u);
  EXPECT_EQ(results.runs[0].seed, 7u);  // seeds in the experiment's order: 7 before 3
  EXPECT_EQ(results.runs[1].seed, 3u);
  EXPECT_EQ(results.runs[2].problem, 1u);
  EXPECT_EQ(results.runs[2].length, 3.0);

  const json written = experiment_results_json(e, results);
  EXPECT_FALSE(written["complete"]);
  EXPECT_EQ(written["missing_runs"], 5);
  std::ostringstream log, tables;
  write_ompl_benchmark_log(log, e, results);
  EXPECT_NE(log.str().find("incomplete: 5 of 8 runs missing\n"), std::string::npos);
  write_experiment_tables(tables, e, results);
  EXPECT_NE(tables.str().find("**Incomplete:** 5 of 8 runs missing"), std::string::npos);
}

TEST(ExperimentFile, RefusesARepeatedSeed) {
  try {
    parse_experiment(R"({"problems": [{"name": "office", "file": "../worlds/office.json"}],
        "planners": [{"name": "rrt", "planner": "rrt"}], "seeds": [1, 2, 1], "time_limit": 5})",
                     kRecordsFolderFile);
    ADD_FAILURE() << "accepted";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("seeds[2]: 1 repeats seeds[0]"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace polyplan
