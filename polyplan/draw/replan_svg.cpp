#include <polyplan/draw/replan_svg.hpp>

#include <polyplan/draw/theme.hpp>

#include <string>
#include <vector>

namespace polyplan {
namespace {

// Cell (x, y) of the map as a unit square, the file's first row at the top.
svg::Box2 cell_box(const ReplanResult& r, int x, int y) {
  const double top = r.height - y;
  return {static_cast<double>(x), top - 1, x + 1.0, top};
}
svg::Point2 centre(const ReplanResult& r, GridPoint p) { return {p.x + 0.5, r.height - p.y - 0.5}; }

std::vector<svg::Point2> centres(const ReplanResult& r, const std::vector<GridPoint>& cells) {
  std::vector<svg::Point2> points;
  for (const GridPoint& p : cells) points.push_back(centre(r, p));
  return points;
}

// The cells' three looks, the same in the picture and in the animation.
struct CellStyles {
  svg::Style free = svg::filled(theme::free_tints[0].fill, 1.0, "none", 0);
  svg::Style unseen = svg::filled(theme::blocked_cell_fill, 0.55, "none", 0);
  svg::Style seen = svg::filled(theme::obstacle_fill, 1.0, "none", 0);
  void legend(svg::Drawing& drawing, const char* unseen_label) const {
    drawing.legend("seen free", free, svg::Swatch::area);
    drawing.legend("blocked, seen", seen, svg::Swatch::area);
    drawing.legend(unseen_label, unseen, svg::Swatch::area);
  }
};

void draw_cells(svg::Drawing& drawing, const ReplanResult& r) {
  std::vector<svg::Box2> seen_free, seen_blocked, unseen_blocked;
  for (int y = 0; y < r.height; ++y)
    for (int x = 0; x < r.width; ++x) {
      const CellKnowledge k = r.knowledge[static_cast<std::size_t>(y) * r.width + x];
      if (k == CellKnowledge::free) seen_free.push_back(cell_box(r, x, y));
      if (k == CellKnowledge::blocked) seen_blocked.push_back(cell_box(r, x, y));
      if (k == CellKnowledge::unknown && r.truth.is_blocked(x, y)) unseen_blocked.push_back(cell_box(r, x, y));
    }
  const CellStyles styles;
  drawing.boxes(seen_free, styles.free);
  drawing.boxes(unseen_blocked, styles.unseen);
  drawing.boxes(seen_blocked, styles.seen);
  styles.legend(drawing, "blocked, never seen");
}

// "0;0;1;1" over "0;t;t;1": hidden until t of the loop, then shown to its end.
std::string appear_at(double t, const std::string& timing) {
  const std::string at = svg::format_number(t);
  return "<animate attributeName=\"opacity\" calcMode=\"discrete\" " + timing + " values=\"0;1;1\" keyTimes=\"0;" + at +
         ";1\"/>";
}

void draw_cells_as_seen(svg::Drawing& drawing, const ReplanResult& r, double frames, const std::string& timing) {
  // Cells grouped by the move after which they were first sensed: one path per group and kind.
  std::vector<std::vector<svg::Box2>> free_by_move(r.moves + 1), blocked_by_move(r.moves + 1);
  std::vector<svg::Box2> blocked;
  for (int y = 0; y < r.height; ++y)
    for (int x = 0; x < r.width; ++x) {
      const std::size_t c = static_cast<std::size_t>(y) * r.width + x, m = r.seen_after[c];
      // Every blocked cell pale until it is seen, dark from then on.
      if (r.truth.is_blocked(x, y)) blocked.push_back(cell_box(r, x, y));
      if (m != never_seen)
        (r.knowledge[c] == CellKnowledge::blocked ? blocked_by_move : free_by_move)[m].push_back(cell_box(r, x, y));
    }
  const CellStyles styles;
  drawing.boxes(blocked, styles.unseen);
  for (std::size_t m = 0; m <= r.moves; ++m)
    for (const auto& [cells, style] :
         {std::pair{&free_by_move[m], &styles.free}, std::pair{&blocked_by_move[m], &styles.seen}}) {
      if (cells->empty()) continue;
      drawing.begin_group("opacity=\"0\"", appear_at(m / frames, timing));
      drawing.boxes(*cells, *style);
      drawing.end_group();
    }
  styles.legend(drawing, "blocked, not yet seen");
}

void draw_frame_and_title(svg::Drawing& drawing, const ReplanResult& r, const std::string& title) {
  drawing.polyline({{0, 0}, {double(r.width), 0}, {double(r.width), double(r.height)}, {0, double(r.height)}, {0, 0}},
                   svg::Style{"none", theme::bounds, 1, 1, 1, ""});
  const svg::Box2 v = drawing.view();
  drawing.text({v.xmin + 0.02 * (v.xmax - v.xmin), v.ymax - 0.03 * (v.ymax - v.ymin)}, title, 14);
}

}  // namespace

std::string replan_title(const ReplanResult& r) {
  return "polyplan replan " + r.truth.source + " (" + std::string(to_string(r.algorithm)) + ")";
}

svg::Drawing draw_replan_animation(const ReplanResult& r, const std::string& title, double seconds_per_move) {
  svg::Drawing drawing({0, 0, static_cast<double>(r.width), static_cast<double>(r.height)});
  // One frame per move and one more at the end, held, before the loop starts again.
  const double frames = static_cast<double>(r.moves) + 2;
  const std::string timing =
      "dur=\"" + svg::format_number(frames * seconds_per_move) + "s\" repeatCount=\"indefinite\"";
  draw_cells_as_seen(drawing, r, frames, timing);
  draw_frame_and_title(drawing, r, title);
  const svg::Style driven{"none", theme::path_colour(0), 2.5, 1, 0.35, ""};
  drawing.polyline(centres(r, r.traversed), driven);
  drawing.legend("traversed", driven, svg::Swatch::line);
  std::string xs, ys, times;
  for (std::size_t m = 0; m < r.traversed.size(); ++m) {
    const svg::Point2 s = drawing.to_screen(centre(r, r.traversed[m]));
    const std::string sep = m ? ";" : "";
    xs += sep + svg::format_number(s.x);
    ys += sep + svg::format_number(s.y);
    times += sep + svg::format_number(m / frames);
  }
  xs += ";" + xs.substr(xs.rfind(';') + 1);  // held at the last cell to the loop's end
  ys += ";" + ys.substr(ys.rfind(';') + 1);
  times += ";1";
  const svg::Point2 at = drawing.to_screen(centre(r, r.traversed.front()));
  const std::string keyed = timing + " calcMode=\"discrete\" keyTimes=\"" + times + "\"";
  drawing.raw("<circle cx=\"" + svg::format_number(at.x) + "\" cy=\"" + svg::format_number(at.y) +
              "\" r=\"6\" fill=\"" + theme::start +
              "\" stroke=\"#fff\" stroke-width=\"1.5\">\n<animate attributeName=\"cx\" " + keyed + " values=\"" + xs +
              "\"/>\n<animate attributeName=\"cy\" " + keyed + " values=\"" + ys + "\"/>\n</circle>");
  drawing.legend("the robot", svg::Style{theme::start, "#fff", 1.5, 1, 1, ""}, svg::Swatch::dot);
  const svg::Style goal{theme::goal, theme::goal, 1, 1, 1, ""};
  if (r.found) {
    drawing.points({centre(r, r.traversed.back())}, 5, goal);
    drawing.legend("goal", goal, svg::Swatch::dot);
  }
  return drawing;
}

svg::Drawing draw_replan(const ReplanResult& r, const std::string& title) {
  svg::Drawing drawing({0, 0, static_cast<double>(r.width), static_cast<double>(r.height)});
  draw_cells(drawing, r);
  if (r.last_plan.size() > 1) {
    const svg::Style planned{"none", theme::path_colour(1), 2, 1, 1, "5 4"};
    drawing.polyline(centres(r, r.last_plan), planned);
    drawing.legend("last plan", planned, svg::Swatch::line);
  }
  const svg::Style driven{"none", theme::path_colour(0), 2.5, 1, 1, ""};
  drawing.polyline(centres(r, r.traversed), driven);
  drawing.legend("traversed", driven, svg::Swatch::line);
  const svg::Style start{theme::start, theme::start, 1, 1, 1, ""}, goal{theme::goal, theme::goal, 1, 1, 1, ""};
  drawing.points({centre(r, r.traversed.front())}, 5, start);
  drawing.legend("start", start, svg::Swatch::dot);
  if (!r.steps.empty() || r.found) {
    drawing.points({centre(r, r.found ? r.traversed.back() : r.steps.back().at)}, 5,
                   r.found ? goal : svg::Style{"#fff", theme::goal, 2, 1, 1, ""});
    drawing.legend(r.found ? "goal" : "where it gave up", r.found ? goal : svg::Style{"#fff", theme::goal, 2, 1, 1, ""},
                   svg::Swatch::dot);
  }
  draw_frame_and_title(drawing, r, title);
  return drawing;
}

}  // namespace polyplan
