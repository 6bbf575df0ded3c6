#include <polyplan/problem/report_pictures.hpp>

#include <polyplan/geometry/input_error.hpp>
#include <polyplan/problem/detail/space_door.hpp>

namespace polyplan {

std::vector<Picture> draw_reports(const Problem& problem, const std::vector<const Report*>& reports,
                                  const PictureOptions& options) {
  const std::string_view space = reports.empty() ? std::string_view() : reports.front()->space();
  for (const Report* r : reports)
    if (r->space() != space)
      throw InputError("the plans to draw mix planners of different spaces (" + std::string(space) + ", " +
                       std::string(r->space()) + ")");
  std::vector<Picture> pictures;
  const bool drawn = detail::any_space([&](auto tag) {
    using Space = typename decltype(tag)::Space;
    const auto& door = detail::space_door<Space>();
    if (!door.plans(problem) || (!reports.empty() && space != Space::description)) return false;
    pictures = door.draw(problem, reports, options);
    return true;
  });
  if (!drawn) throw InputError("the plans were not planned in " + problem.source());
  return pictures;
}

}  // namespace polyplan
