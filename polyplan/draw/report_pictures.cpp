#include <polyplan/draw/report_pictures.hpp>

#include <polyplan/draw/arm_svg.hpp>
#include <polyplan/draw/car_svg.hpp>
#include <polyplan/draw/plan_svg.hpp>
#include <polyplan/draw/pose_svg.hpp>
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/input_error.hpp>

#include <type_traits>

namespace polyplan {
namespace {

// The reports' answers, all of configuration C (the first report's).
template <class Configuration>
std::vector<PlanReport<Configuration>> typed_reports(const std::vector<const Report*>& reports) {
  std::vector<PlanReport<Configuration>> typed;
  for (const Report* r : reports) typed.push_back(std::get<PlanReport<Configuration>>(r->typed()));
  return typed;
}

// The file's name without its folders, for a picture's title.
std::string file_name(const std::string& path) { return path.substr(path.find_last_of('/') + 1); }

// An arm's reports, one picture each: its motion animated, or strobed.
std::vector<Picture> arm_pictures(const ArmProblem& arm, const std::vector<const Report*>& reports,
                                  const PictureOptions& options) {
  if (reports.empty()) {  // the arm alone: at its first query's start (or stretched out), among its obstacles
    PlanReport<JointAngles> standing;
    standing.path = {arm.queries.empty() ? JointAngles(arm.arm.joints(), 0.0) : arm.queries.front().start};
    return {
        {"", draw_plan(arm, standing, {ArmPictureOptions::Kind::strobe, file_name(arm.source), 1, 1, std::nullopt})}};
  }
  std::vector<Picture> pictures;
  for (const Report* r : reports) {
    const ArmPictureOptions picture{
        options.strobe ? ArmPictureOptions::Kind::strobe : ArmPictureOptions::Kind::animation,
        file_name(arm.source) + " · " + r->query() + " · " + r->planner() + options.settings, options.every_kth, 1,
        r->target};
    pictures.push_back({r->query(), draw_plan(arm, std::get<PlanReport<JointAngles>>(r->typed()), picture)});
  }
  return pictures;
}

// A world's reports of configuration C in one picture: over its C-space for a translating robot,
// over the world itself for poses and a car's states.
template <class Configuration>
svg::Drawing world_picture(const Problem& problem, const std::vector<PlanReport<Configuration>>& reports) {
  if constexpr (std::is_same_v<Configuration, ExactPoint>) {
    if (!round_features(*problem.world()).empty()) return draw_plan(problem.round_world(), reports);
    return draw_plan(problem.cspace(), reports);
  } else return draw_plan(*problem.world(), reports);
}

}  // namespace

std::vector<Picture> draw_reports(const Problem& problem, const std::vector<const Report*>& reports,
                                  const PictureOptions& options) {
  for (const Report* r : reports)
    if (r->space() != reports.front()->space())
      throw InputError("the plans to draw mix planners of different spaces (" + std::string(reports.front()->space()) +
                       ", " + std::string(r->space()) + ")");
  const bool arm_reports =
      !reports.empty() && std::holds_alternative<PlanReport<JointAngles>>(reports.front()->typed());
  if (!reports.empty() && arm_reports != (problem.arm() != nullptr))
    throw InputError("the plans were not planned in " + problem.source());
  if (problem.arm()) return arm_pictures(*problem.arm(), reports, options);
  if (reports.empty())  // the world alone
    return {Picture{"", problem.world()->robot.car ? world_picture<CarState>(problem, {})
                                                   : world_picture<ExactPoint>(problem, {})}};
  return std::visit(
      [&](const auto& first) -> std::vector<Picture> {
        using Configuration = typename std::decay_t<decltype(first.path)>::value_type;
        if constexpr (std::is_same_v<Configuration, JointAngles>) return {};  // an arm's: answered above
        else return {Picture{"", world_picture(problem, typed_reports<Configuration>(reports))}};
      },
      reports.front()->typed());
}

}  // namespace polyplan
