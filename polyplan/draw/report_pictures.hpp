#pragma once
// The pictures of a problem's reports, whatever kind of problem it is: a world with all its
// reports' paths in one picture (the C-space, the roadmap or cells a report recorded), an arm's
// motion one picture per report (an animation, or a strobe of its configurations).
#include <polyplan/draw/svg.hpp>
#include <polyplan/registry/problem.hpp>
#include <polyplan/registry/report.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace polyplan {

struct PictureOptions {
  // An arm: every k-th configuration at once (k = every_kth, or about a dozen when 0) instead of
  // the animation. A world's picture is one drawing whatever this says.
  bool strobe = false;
  std::size_t every_kth = 0;
  // Added to an arm picture's title (file · query · planner): the options that were set.
  std::string settings;
};

struct Picture {
  std::string query;  // the one query it shows; empty when it shows every report
  svg::Drawing drawing;
};

// InputError when the reports are not all of one space planned in `problem`.
std::vector<Picture> draw_reports(const Problem& problem, const std::vector<const Report*>& reports,
                                  const PictureOptions& options = {});

}  // namespace polyplan
