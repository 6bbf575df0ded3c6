#pragma once
// Runs every cell of an experiment (problem × planner entry × seed), each run alone in its thread,
// on `threads` threads: each thread reads the problem files it meets itself and builds a planner
// per run, so that no planner, C-space or exact number is shared between threads.
#include <polyplan/experiment/experiment.hpp>

#include <cstddef>
#include <functional>

namespace polyplan {

// Called after each run (from the thread that ran it, one call at a time) with the runs done and
// the runs in all.
using ExperimentProgress = std::function<void(std::size_t done, std::size_t total)>;

// The runs in cell order. A run whose planner throws (a bug, not an answer) is recorded as not
// found with the exception's message in why_not, so that one run cannot lose a long experiment.
ExperimentResults run_experiment(const Experiment& experiment, unsigned threads,
                                 const ExperimentProgress& progress = {});

}  // namespace polyplan
