#include <polyplan/draw/svg.hpp>

#include <polyplan/geometry/input_error.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <numbers>
#include <stdexcept>

namespace polyplan::svg {

Style filled(const std::string& fill, double fill_opacity, const std::string& stroke, double stroke_px) {
  Style s;
  s.fill = fill;
  s.fill_opacity = fill_opacity;
  s.stroke = stroke;
  s.stroke_px = stroke_px;
  return s;
}

namespace {

constexpr const char* kFontFamily = "DejaVu Sans, Helvetica, Arial, sans-serif";
constexpr double kLegendFontPx = 13;
constexpr double kLegendRowPx = 18;
constexpr double kLegendPadPx = 8;    // between the legend box and the picture's edge
constexpr double kLegendInsetPx = 6;  // between the box's edge and its first row
constexpr double kLegendSwatchPx = 22;
constexpr double kLegendCharPx = 0.58 * kLegendFontPx;  // a generous average glyph width

constexpr double kInkCellPx = 8;
constexpr bool kInkEdge = false;
constexpr bool kInkImportant = true;

bool finite(double v) { return std::isfinite(v); }

// UTF-8 code points, for estimating the width of a label.
std::size_t glyph_count(const std::string& text) {
  std::size_t n = 0;
  for (unsigned char c : text) n += (c & 0xC0) != 0x80;
  return n;
}

// Pixel coordinates: 8 significant digits keep 1e-5 px in a picture of a few thousand pixels,
// whatever the world's scale (the world was mapped to pixels in double precision).
void append_px(std::string& out, double value) {
  if (!finite(value) || value == 0) {  // also turns -0 into 0
    out += '0';
    return;
  }
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.8g", value);
  out += buffer;
}

void append_attribute(std::string& out, const char* name, double value) {
  out += ' ';
  out += name;
  out += "=\"";
  append_px(out, value);
  out += '"';
}

bool is_none(const std::string& paint) { return paint.empty() || paint == "none"; }

// A dash array of non-negative numbers, normalised to "a b c"; empty when it is not one.
std::string dash_array(const std::string& dash) {
  std::string out;
  const char* s = dash.c_str();
  while (*s) {
    if (*s == ' ' || *s == ',') {
      ++s;
      continue;
    }
    char* end = nullptr;
    const double v = std::strtod(s, &end);
    if (end == s || !finite(v) || v < 0) return {};
    if (!out.empty()) out += ' ';
    append_px(out, v);
    s = end;
  }
  return out;
}

void append_style(std::string& out, const Style& style) {
  out += " fill=\"";
  out += is_none(style.fill) ? std::string("none") : escape_xml(style.fill);
  out += '"';
  if (!is_none(style.fill) && style.fill_opacity != 1) {
    append_attribute(out, "fill-opacity", std::clamp(style.fill_opacity, 0.0, 1.0));
  }
  if (is_none(style.stroke) || !(style.stroke_px > 0)) {
    out += " stroke=\"none\"";
  } else {
    out += " stroke=\"";
    out += escape_xml(style.stroke);
    out += '"';
    append_attribute(out, "stroke-width", style.stroke_px);
    if (const std::string dashes = dash_array(style.dash); !dashes.empty()) {
      out += " stroke-dasharray=\"";
      out += dashes;
      out += "\" stroke-linecap=\"butt\"";
    }
  }
  if (style.opacity != 1) append_attribute(out, "opacity", std::clamp(style.opacity, 0.0, 1.0));
}

}  // namespace

std::string format_number(double value) {
  std::string out;
  append_px(out, value);
  return out;
}

std::string escape_xml(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char ch : text) {
    const auto c = static_cast<unsigned char>(ch);
    switch (ch) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default:
        // XML 1.0 forbids most control characters even as references; a label never needs them.
        if (c < 0x20 && c != '\t' && c != '\n' && c != '\r') break;
        out += ch;
    }
  }
  return out;
}

Drawing::Drawing(Box2 box, double width_px) {
  if (!finite(box.xmin) || !finite(box.ymin) || !finite(box.xmax) || !finite(box.ymax)) {
    box = {0, 0, 1, 1};
  }
  if (box.xmin > box.xmax) std::swap(box.xmin, box.xmax);
  if (box.ymin > box.ymax) std::swap(box.ymin, box.ymax);
  double w = box.xmax - box.xmin;
  double h = box.ymax - box.ymin;
  // A degenerate or extremely flat box would give a picture with no room to see anything.
  const double larger = std::max(w, h);
  const double min_side = larger > 0 ? larger / 20 : 1;
  if (w < min_side) {
    const double c = (box.xmin + box.xmax) / 2;
    box.xmin = c - min_side / 2;
    box.xmax = c + min_side / 2;
    w = min_side;
  }
  if (h < min_side) {
    const double c = (box.ymin + box.ymax) / 2;
    box.ymin = c - min_side / 2;
    box.ymax = c + min_side / 2;
    h = min_side;
  }
  const double margin = 0.04 * std::max(w, h);
  view_ = {box.xmin - margin, box.ymin - margin, box.xmax + margin, box.ymax + margin};

  width_px_ = finite(width_px) && width_px > 0 ? width_px : 800;
  scale_ = width_px_ / (view_.xmax - view_.xmin);
  height_px_ = (view_.ymax - view_.ymin) * scale_;

  ink_columns_ = static_cast<std::size_t>(std::ceil(width_px_ / kInkCellPx));
  ink_rows_ = static_cast<std::size_t>(std::ceil(height_px_ / kInkCellPx));
  ink_.assign(ink_columns_ * ink_rows_, Ink{});
}

Point2 Drawing::to_screen(Point2 p) const { return {(p.x - view_.xmin) * scale_, (view_.ymax - p.y) * scale_}; }

void Drawing::append_point(std::string& out, Point2 world) const {
  const Point2 s = to_screen(world);
  append_px(out, s.x);
  out += ' ';
  append_px(out, s.y);
}

void Drawing::mark_ink(Point2 world, bool important) {
  if (moving_groups_ > 0) return;
  const Point2 p = to_screen(world);
  if (!(p.x >= 0 && p.y >= 0)) return;  // also NaN
  const double col = p.x / kInkCellPx, row = p.y / kInkCellPx;
  if (col < static_cast<double>(ink_columns_) && row < static_cast<double>(ink_rows_)) {
    Ink& cell = ink_[static_cast<std::size_t>(row) * ink_columns_ + static_cast<std::size_t>(col)];
    (important ? cell.important : cell.edges) += 1;
  }
}

void Drawing::mark_ink(Point2 a, Point2 b, bool important) {
  if (moving_groups_ > 0) return;
  const Point2 sa = to_screen(a), sb = to_screen(b);
  // Entirely beyond one side of the picture: nothing to mark.
  if ((sa.x < 0 && sb.x < 0) || (sa.y < 0 && sb.y < 0) || (sa.x > width_px_ && sb.x > width_px_) ||
      (sa.y > height_px_ && sb.y > height_px_)) {
    return;
  }
  const double length = std::hypot(sb.x - sa.x, sb.y - sa.y);
  if (!finite(length)) return;
  const double most = 4.0 * static_cast<double>(ink_columns_ + ink_rows_);
  const auto steps = static_cast<std::size_t>(std::min(std::ceil(length / (kInkCellPx / 2)), most));
  for (std::size_t i = 0; i <= steps; ++i) {
    const double t = steps == 0 ? 0 : static_cast<double>(i) / static_cast<double>(steps);
    mark_ink({a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t}, important);
  }
}

Drawing::Ink Drawing::ink_in(double x0, double y0, double x1, double y1) const {
  const auto cell = [](double v, std::size_t n) {
    return std::min(n, static_cast<std::size_t>(std::max(0.0, v / kInkCellPx)));
  };
  Ink total;
  for (std::size_t r = cell(y0, ink_rows_); r < std::min(ink_rows_, cell(y1, ink_rows_) + 1); ++r) {
    for (std::size_t c = cell(x0, ink_columns_); c < std::min(ink_columns_, cell(x1, ink_columns_) + 1); ++c) {
      total.important += ink_[r * ink_columns_ + c].important;
      total.edges += ink_[r * ink_columns_ + c].edges;
    }
  }
  return total;
}

void Drawing::polygon(const std::vector<std::vector<Point2>>& rings, const Style& style) {
  std::string d;
  for (const auto& ring : rings) {
    if (ring.size() < 2) continue;
    d += d.empty() ? "M" : "\nM";
    append_point(d, ring[0]);
    d += 'L';
    for (std::size_t i = 1; i < ring.size(); ++i) {
      if (i > 1) d += ' ';
      append_point(d, ring[i]);
    }
    d += 'Z';
    for (std::size_t i = 0; i < ring.size(); ++i) mark_ink(ring[i], ring[(i + 1) % ring.size()], kInkEdge);
  }
  if (d.empty()) return;
  body_ += "<path fill-rule=\"evenodd\"";
  append_style(body_, style);
  body_ += " d=\"";
  body_ += d;
  body_ += "\"/>\n";
}

void Drawing::polyline(const std::vector<Point2>& points, const Style& style) {
  if (points.empty()) return;
  mark_ink(points[0], kInkImportant);
  for (std::size_t i = 1; i < points.size(); ++i) mark_ink(points[i - 1], points[i], kInkImportant);
  body_ += "<path";
  append_style(body_, style);
  body_ += " d=\"M";
  append_point(body_, points[0]);
  // A single point still shows as a dot thanks to the round caps.
  body_ += 'L';
  for (std::size_t i = points.size() == 1 ? 0 : 1; i < points.size(); ++i) {
    if (i > 1) body_ += ' ';
    append_point(body_, points[i]);
  }
  body_ += "\"/>\n";
}

void Drawing::segments(const std::vector<std::pair<Point2, Point2>>& segs, const Style& style) {
  if (segs.empty()) return;
  body_ += "<path";
  append_style(body_, style);
  body_ += " d=\"";
  bool first = true;
  Point2 last{};
  std::size_t moves = 0;
  for (const auto& [a, b] : segs) {
    mark_ink(a, b, kInkEdge);
    // Chained segments (a path given edge by edge) need no new move-to.
    if (first || a.x != last.x || a.y != last.y) {
      if (!first) body_ += (++moves % 64 == 0) ? '\n' : ' ';
      body_ += 'M';
      append_point(body_, a);
    }
    body_ += 'L';
    append_point(body_, b);
    last = b;
    first = false;
  }
  body_ += "\"/>\n";
}

void Drawing::curves(const std::vector<std::array<Point2, 3>>& arcs, const Style& style) {
  if (arcs.empty()) return;
  body_ += "<path";
  append_style(body_, style);
  body_ += " d=\"";
  std::size_t count = 0;
  for (const auto& [from, control, to] : arcs) {
    mark_ink(from, control, kInkEdge);  // the control polygon holds the curve
    mark_ink(control, to, kInkEdge);
    if (count++) body_ += (count % 64 == 0) ? '\n' : ' ';
    body_ += 'M';
    append_point(body_, from);
    body_ += 'Q';
    append_point(body_, control);
    body_ += ' ';
    append_point(body_, to);
  }
  body_ += "\"/>\n";
}

void Drawing::boxes(const std::vector<Box2>& boxes, const Style& style) {
  if (boxes.empty()) return;
  body_ += "<path fill-rule=\"evenodd\"";
  append_style(body_, style);
  body_ += " d=\"";
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const Box2& b = boxes[i];
    mark_ink({b.xmin, b.ymin}, {b.xmax, b.ymin}, kInkEdge);
    mark_ink({b.xmax, b.ymin}, {b.xmax, b.ymax}, kInkEdge);
    mark_ink({b.xmax, b.ymax}, {b.xmin, b.ymax}, kInkEdge);
    mark_ink({b.xmin, b.ymax}, {b.xmin, b.ymin}, kInkEdge);
    const Point2 p = to_screen({b.xmin, b.ymin}), q = to_screen({b.xmax, b.ymax});
    if (i > 0) body_ += (i % 16 == 0) ? '\n' : ' ';
    body_ += 'M';
    append_px(body_, p.x);
    body_ += ' ';
    append_px(body_, p.y);
    body_ += 'H';
    append_px(body_, q.x);
    body_ += 'V';
    append_px(body_, q.y);
    body_ += 'H';
    append_px(body_, p.x);
    body_ += 'Z';
  }
  body_ += "\"/>\n";
}

void Drawing::circles(const std::vector<Circle2>& circles, const Style& style) {
  if (circles.empty()) return;
  body_ += "<g";
  append_style(body_, style);
  body_ += ">\n";
  for (const Circle2& c : circles) {
    for (int i = 0; i < 16; ++i) {  // the ink of the inscribed 16-gon: near enough for the legend
      const double a = 2 * std::numbers::pi * i / 16, b = 2 * std::numbers::pi * (i + 1) / 16;
      mark_ink({c.centre.x + c.radius * std::cos(a), c.centre.y + c.radius * std::sin(a)},
               {c.centre.x + c.radius * std::cos(b), c.centre.y + c.radius * std::sin(b)}, kInkEdge);
    }
    const Point2 s = to_screen(c.centre);
    body_ += "<circle cx=\"";
    append_px(body_, s.x);
    body_ += "\" cy=\"";
    append_px(body_, s.y);
    body_ += "\" r=\"";
    append_px(body_, std::max(0.0, c.radius * scale_));
    body_ += "\"/>\n";
  }
  body_ += "</g>\n";
}

void Drawing::points(const std::vector<Point2>& pts, double radius_px, const Style& style) {
  if (pts.empty() || !(radius_px > 0)) return;
  body_ += "<g";
  append_style(body_, style);
  body_ += ">\n";
  std::string r;
  append_px(r, radius_px);
  for (const Point2& p : pts) {
    mark_ink(p, kInkImportant);
    const Point2 s = to_screen(p);
    body_ += "<circle cx=\"";
    append_px(body_, s.x);
    body_ += "\" cy=\"";
    append_px(body_, s.y);
    body_ += "\" r=\"";
    body_ += r;
    body_ += "\"/>\n";
  }
  body_ += "</g>\n";
}

void Drawing::text(Point2 at, const std::string& content, double size_px) {
  if (!(size_px > 0)) return;
  const double text_width = 0.6 * size_px * static_cast<double>(glyph_count(content)) / scale_;
  mark_ink(at, {at.x + text_width, at.y}, kInkImportant);
  const Point2 s = to_screen(at);
  body_ += "<text";
  append_attribute(body_, "x", s.x);
  append_attribute(body_, "y", s.y);
  append_attribute(body_, "font-size", size_px);
  body_ += " fill=\"#222\" stroke=\"#fff\" stroke-width=\"3\" stroke-opacity=\"0.8\" paint-order=\"stroke\">";
  body_ += escape_xml(content);
  body_ += "</text>\n";
}

void Drawing::legend(const std::string& label, const Style& style, Swatch swatch) {
  legend_.push_back({label, style, swatch});
}

void Drawing::begin_group(const std::string& attributes, const std::string& children, GroupContent content) {
  body_ += "<g";
  if (!attributes.empty()) {
    body_ += ' ';
    body_ += attributes;
  }
  body_ += ">\n";
  body_ += children;
  if (!children.empty() && children.back() != '\n') body_ += '\n';
  open_groups_.push_back(content);
  if (content == GroupContent::moves) ++moving_groups_;
}

void Drawing::end_group() {
  if (open_groups_.empty()) throw std::logic_error("svg::Drawing::end_group: no group is open");
  if (open_groups_.back() == GroupContent::moves) --moving_groups_;
  open_groups_.pop_back();
  body_ += "</g>\n";
}

void Drawing::keep_clear(const std::vector<Point2>& polyline) {
  if (polyline.size() == 1) mark_ink(polyline[0], kInkImportant);
  for (std::size_t i = 1; i < polyline.size(); ++i) mark_ink(polyline[i - 1], polyline[i], kInkImportant);
}

void Drawing::raw(const std::string& fragment) {
  body_ += fragment;
  if (!fragment.empty() && fragment.back() != '\n') body_ += '\n';
}

Drawing::LegendLayout Drawing::legend_layout() const {
  LegendLayout layout;
  if (legend_.empty()) return layout;
  std::size_t widest = 0;
  for (const auto& e : legend_) widest = std::max(widest, glyph_count(e.label));
  const double entry_width = 8 + kLegendSwatchPx + 8 + kLegendCharPx * static_cast<double>(widest) + 10;
  const std::size_t n = legend_.size();

  // Inside the picture, in the corner that hides least (top-left on a tie), if that hides nothing
  // that matters and the box leaves most of the picture visible.
  layout.column_width = entry_width;
  layout.rows = n;
  layout.width = entry_width;
  layout.height = 2 * kLegendInsetPx + kLegendRowPx * static_cast<double>(n);
  if (layout.width <= 0.7 * width_px_ && layout.height <= 0.7 * height_px_) {
    const double left = kLegendPadPx, top = kLegendPadPx;
    const double right = width_px_ - kLegendPadPx - layout.width;
    const double bottom = height_px_ - kLegendPadPx - layout.height;
    Ink least;
    bool found = false;
    for (const auto& [x, y] :
         {std::pair{left, top}, std::pair{right, top}, std::pair{left, bottom}, std::pair{right, bottom}}) {
      const Ink ink = ink_in(x, y, x + layout.width, y + layout.height);
      if (!found || ink.important < least.important || (ink.important == least.important && ink.edges < least.edges)) {
        least = ink;
        layout.x = x;
        layout.y = y;
        found = true;
      }
    }
    if (least.important == 0) return layout;
  }

  // Otherwise in a band below the picture, in as many columns as fit.
  const double usable = std::max(entry_width, width_px_ - 2 * kLegendPadPx);
  const auto columns = std::clamp<std::size_t>(static_cast<std::size_t>(usable / entry_width), 1, n);
  layout.rows = (n + columns - 1) / columns;
  const std::size_t used_columns = (n + layout.rows - 1) / layout.rows;
  layout.width = entry_width * static_cast<double>(used_columns);
  layout.height = 2 * kLegendInsetPx + kLegendRowPx * static_cast<double>(layout.rows);
  layout.x = kLegendPadPx;
  layout.y = height_px_;  // the picture's bottom margin already separates it from the world
  layout.band = layout.height + kLegendPadPx;
  return layout;
}

void Drawing::append_legend(std::string& out, const LegendLayout& layout) const {
  if (legend_.empty()) return;
  out += "<g font-size=\"";
  append_px(out, kLegendFontPx);
  out += "\">\n<rect";
  append_attribute(out, "x", layout.x);
  append_attribute(out, "y", layout.y);
  append_attribute(out, "width", layout.width);
  append_attribute(out, "height", layout.height);
  out += " rx=\"4\" fill=\"#fff\" fill-opacity=\"0.88\" stroke=\"#999\" stroke-width=\"1\"/>\n";

  for (std::size_t i = 0; i < legend_.size(); ++i) {
    const LegendEntry& e = legend_[i];
    const double column_x = layout.x + layout.column_width * static_cast<double>(i / layout.rows);
    const double mid = layout.y + kLegendInsetPx + kLegendRowPx * (static_cast<double>(i % layout.rows) + 0.5);
    const double sx = column_x + 8;
    Style s = e.style;
    s.stroke_px = std::min(s.stroke_px, 4.0);
    const bool has_fill = !is_none(s.fill);
    const bool has_stroke = !is_none(s.stroke) && s.stroke_px > 0;
    Swatch kind = e.swatch;
    if (kind == Swatch::automatic) kind = has_fill ? Swatch::area : Swatch::line;
    if (kind == Swatch::area) {
      if (!has_stroke) {  // a pale fill needs an edge to be seen in the legend
        s.stroke = "#aaa";
        s.stroke_px = 0.75;
      }
      out += "<rect";
      append_attribute(out, "x", sx);
      append_attribute(out, "y", mid - 6);
      append_attribute(out, "width", kLegendSwatchPx);
      out += " height=\"12\"";
      append_style(out, s);
      out += "/>\n";
    } else if (kind == Swatch::dot) {
      out += "<circle";
      append_attribute(out, "cx", sx + kLegendSwatchPx / 2);
      append_attribute(out, "cy", mid);
      out += " r=\"5\"";
      append_style(out, s);
      out += "/>\n";
    } else {
      if (!has_stroke) {  // a line sample of a fill-only style: show its colour
        s.stroke = has_fill ? s.fill : "#000";
        s.stroke_px = 2;
      }
      s.fill = "none";
      s.stroke_px = std::max(s.stroke_px, 1.5);
      out += "<path d=\"M";
      append_px(out, sx);
      out += ' ';
      append_px(out, mid);
      out += 'h';
      append_px(out, kLegendSwatchPx);
      out += '"';
      append_style(out, s);
      out += "/>\n";
    }
    out += "<text";
    append_attribute(out, "x", sx + kLegendSwatchPx + 8);
    append_attribute(out, "y", mid + 0.35 * kLegendFontPx);
    out += " fill=\"#222\">";
    out += escape_xml(e.label);
    out += "</text>\n";
  }
  out += "</g>\n";
}

std::string Drawing::str() const {
  const LegendLayout layout = legend_layout();
  const double height = height_px_ + layout.band;
  std::string out;
  out.reserve(body_.size() + 2048);
  out += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\"";
  append_attribute(out, "width", width_px_);
  append_attribute(out, "height", height);
  out += " viewBox=\"0 0 ";
  append_px(out, width_px_);
  out += ' ';
  append_px(out, height);
  out += "\" font-family=\"";
  out += kFontFamily;
  out += "\" stroke-linejoin=\"round\" stroke-linecap=\"round\">\n";
  out += "<rect x=\"0\" y=\"0\"";
  append_attribute(out, "width", width_px_);
  append_attribute(out, "height", height);
  out += " fill=\"#fff\"/>\n";
  out += body_;
  for (std::size_t i = 0; i < open_groups_.size(); ++i) out += "</g>\n";
  append_legend(out, layout);
  out += "</svg>\n";
  return out;
}

void Drawing::write(const std::string& path) const {
  const std::string content = str();
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  // The path is the user's: a directory or an unwritable place is bad input, not a bug.
  if (!file) throw InputError(path + ": cannot write the SVG file: " + std::strerror(errno));
  file.write(content.data(), static_cast<std::streamsize>(content.size()));
  file.close();
  if (!file) throw InputError(path + ": cannot write the SVG file: the write failed (disk full?)");
}

}  // namespace polyplan::svg
