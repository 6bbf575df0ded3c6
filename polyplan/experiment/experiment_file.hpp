#pragma once
// Reading an experiment file (docs/benchmark.md):
//
//   {"name": "rrt-goal-bias",
//    "problems": [{"name": "office", "file": "../worlds/office.json", "query": "start/goal"}, ...],
//    "planners": [{"name": "rrt-bias0.05", "planner": "rrt", "options": {"goal-bias": 0.05}}, ...],
//    "seeds": [1, 2, 3], "time_limit": 10, "cost_times": [1, 2, 5, 10]}
//
// Problem files are world or arm files, relative to the experiment file; a problem's "kind"
// ("world" or "arm") may say which, otherwise an arm file is the one with "links". "query" names
// one of the file's queries (or gives its index; the first by default). Option names and values
// are the registry's (`polyplan planners`), checked by building each planner entry on each problem;
// "seed" and "time" are the experiment's (seeds, time_limit) and not planner options here.
// "cost_times" (increasing, in (0, time_limit]) defaults to 20 even steps up to time_limit.
// Every problem throws InputError with one line "<file>: <object>: <what is wrong>", e.g.
// "exp.json: planners[1].options.k: unknown option for rrt (options: goal-bias, step, ...)".
#include <polyplan/experiment/experiment.hpp>

#include <string>

namespace polyplan {

Experiment read_experiment(const std::string& path);
// The same from text already in memory; `name` stands for the file in messages, and problem files
// resolve against its folder.
Experiment parse_experiment(const std::string& text, const std::string& name);

}  // namespace polyplan
