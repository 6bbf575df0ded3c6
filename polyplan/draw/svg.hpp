#pragma once
// A small SVG writer for pictures of worlds, C-spaces, roadmaps and paths. Standard library only:
// it takes doubles (exact coordinates are converted by the caller, see draw/world_svg.hpp).
//
// Coordinates given to Drawing are world coordinates with y up. The picture shows the given box
// plus a margin, and larger y is drawn higher; text is never mirrored. Stroke widths, dash
// lengths, point radii, text sizes and the legend are in screen pixels whatever the world's scale.
//
// The file is written in the picture's own pixel frame (viewBox "0 0 width height"), each world
// point mapped by to_screen(). That frame keeps every renderer honest: librsvg (rsvg-convert)
// silently draws nothing for a viewBox narrower than about 0.002 units, and tools that ignore
// vector-effect="non-scaling-stroke" would draw a 1.5 px stroke 1.5 world units wide.
#include <algorithm>
#include <array>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace polyplan::svg {

struct Point2 {
  double x, y;
};

struct Box2 {
  double xmin, ymin, xmax, ymax;
};

// A circle in world units (a disc obstacle, a C-obstacle grown round a point).
struct Circle2 {
  Point2 centre;
  double radius;
};

// The smallest box around the points it was given, grown one point at a time.
class BoxAround {
 public:
  BoxAround() = default;
  explicit BoxAround(Box2 start) : box_(start), empty_(false) {}
  void add(double x, double y) {
    box_ = empty_
               ? Box2{x, y, x, y}
               : Box2{std::min(box_.xmin, x), std::min(box_.ymin, y), std::max(box_.xmax, x), std::max(box_.ymax, y)};
    empty_ = false;
  }
  // The box, or `none` when no point was added.
  Box2 box_or(Box2 none) const { return empty_ ? none : box_; }

 private:
  Box2 box_{0, 0, 0, 0};
  bool empty_ = true;
};

struct Style {
  std::string fill = "none";
  std::string stroke = "#000";
  double stroke_px = 1.5;
  double fill_opacity = 1.0;
  double opacity = 1.0;
  std::string dash;  // e.g. "4 3", in screen pixels; empty for a solid line
};

// A filled area with an outline: the style most pictures draw regions with.
Style filled(const std::string& fill, double fill_opacity, const std::string& stroke, double stroke_px);

// What a legend entry's swatch looks like. `automatic` draws a filled square when the style has a
// fill and a line sample otherwise.
enum class Swatch { automatic, area, line, dot };

class Drawing {
 public:
  // The picture shows `view_in_world_units` plus a margin of 4% of its larger side on every side,
  // `width_px` wide and as high as the aspect ratio says. An empty, inverted or very flat box is
  // widened (each side at least 1/20 of the other) so that the picture is never degenerate.
  explicit Drawing(Box2 view_in_world_units, double width_px = 800);

  // The rings as one <path> with fill-rule evenodd, so holes (and rings inside holes) show.
  void polygon(const std::vector<std::vector<Point2>>& rings, const Style&);
  void polyline(const std::vector<Point2>&, const Style&);
  // All segments as one <path> (graphs may have 100k edges).
  void segments(const std::vector<std::pair<Point2, Point2>>&, const Style&);
  // Quadratic Bézier curves {from, control, to} as one <path>: a parabolic arc is exactly one.
  void curves(const std::vector<std::array<Point2, 3>>&, const Style&);
  // Axis-aligned boxes (grid cells, say) as one <path>, half the text of as many polygons.
  void boxes(const std::vector<Box2>&, const Style&);
  // Circles of world radii as <circle> elements in one group (arcs drawn as arcs, at any zoom).
  void circles(const std::vector<Circle2>&, const Style&);
  // Circles of `radius_px` screen pixels, filled with style.fill and outlined with style.stroke.
  void points(const std::vector<Point2>&, double radius_px, const Style&);
  // Text whose baseline starts at `at`, upright, `size_px` screen pixels high, dark grey with a
  // thin white halo so that it reads on any background.
  void text(Point2 at, const std::string&, double size_px);
  // Adds an entry to the legend, a white semi-opaque box with a swatch and the label per entry
  // (13 px text). It goes in the top-left corner of the picture, or in the corner that hides the
  // least of the drawing; when every corner would hide a point, a label or a path (or the picture
  // is too small for it), it goes in a band added below the picture instead.
  void legend(const std::string& label, const Style&, Swatch swatch = Swatch::automatic);

  // Everything drawn until the matching end_group() goes in one <g> element: `attributes` are
  // written verbatim into its start tag (class="...", transform="..."), `children` verbatim as its
  // first children (an <animateTransform>, say) — how moving parts are drawn. When the group
  // moves what it holds (a transform or an animation), say GroupContent::moves: what is drawn
  // inside is then left out of where the legend looks for room, as it is not where it was given.
  // str() closes the groups still open (before the legend, which is never inside one).
  enum class GroupContent { in_place, moves };
  void begin_group(const std::string& attributes, const std::string& children = {},
                   GroupContent content = GroupContent::in_place);
  // Throws std::logic_error when no group is open.
  void end_group();
  // An SVG fragment in the picture's pixel frame (see to_screen), written verbatim: what the
  // writer has no call for (<defs>, an <animate>d circle). Left out of where the legend looks.
  void raw(const std::string& fragment);
  // Draws nothing, but keeps the legend off the polyline as off a drawn path: where a moving
  // part will pass, say.
  void keep_clear(const std::vector<Point2>& polyline);

  std::string str() const;
  // Throws std::runtime_error naming the file if it cannot be written.
  void write(const std::string& path) const;

  // Where a world point lands in the picture, in pixels from its top-left corner (y grows
  // downwards). These are the coordinates written to the file.
  Point2 to_screen(Point2 world) const;
  // The visible world box (the given box plus the margin).
  Box2 view() const { return view_; }
  // Screen pixels per world unit.
  double scale() const { return scale_; }
  double width_px() const { return width_px_; }
  // The height of the world picture; str()'s height attribute adds the legend band, if any.
  double height_px() const { return height_px_; }

 private:
  struct LegendEntry {
    std::string label;
    Style style;
    Swatch swatch;
  };
  struct LegendLayout {
    double x = 0, y = 0;           // the box's top-left corner, px
    double width = 0, height = 0;  // the box, px
    std::size_t rows = 0;          // entries per column
    double column_width = 0;
    double band = 0;  // px added below the world picture (0 when the legend is inside it)
  };

  void append_point(std::string& out, Point2 world) const;  // "x y" in the pixel frame
  void append_legend(std::string& out, const LegendLayout&) const;
  LegendLayout legend_layout() const;
  // A coarse map of what is drawn where, for placing the legend: edges may be hidden a little;
  // points, labels and paths ("important") should not be hidden at all.
  struct Ink {
    double important = 0, edges = 0;
  };
  void mark_ink(Point2 world, bool important);
  void mark_ink(Point2 a, Point2 b, bool important);
  Ink ink_in(double x0, double y0, double x1, double y1) const;  // a pixel rectangle

  Box2 view_{};
  double width_px_ = 800;
  double height_px_ = 800;
  double scale_ = 1;  // px per world unit
  std::string body_;
  std::vector<LegendEntry> legend_;
  std::size_t ink_columns_ = 0, ink_rows_ = 0;
  std::vector<Ink> ink_;
  std::vector<GroupContent> open_groups_;
  std::size_t moving_groups_ = 0;  // open groups that move their content: no ink is marked
};

// `text` with the XML special characters escaped (and characters XML forbids dropped).
std::string escape_xml(const std::string& text);

// A number as the writer prints pixel coordinates (8 significant digits, never "-0", "0" for
// NaN and infinities), for fragments given to Drawing::raw or begin_group.
std::string format_number(double value);

}  // namespace polyplan::svg
