#pragma once
// Reading the SVG text that draw/ writes, for the draw/ tests: attributes, numbers, nesting, the
// picture's body and its legend (svg::Drawing writes the legend last, as one <g font-size=...>).
#include <cstddef>
#include <sstream>
#include <string>
#include <vector>

namespace polyplan::test {

inline std::size_t count(const std::string& text, const std::string& needle) {
  std::size_t n = 0;
  for (auto pos = text.find(needle); pos != std::string::npos; pos = text.find(needle, pos + 1)) ++n;
  return n;
}

// The value of attribute `name` in the tag starting at `pos`; empty when the tag has none.
inline std::string attribute_at(const std::string& svg, std::size_t pos, const std::string& name) {
  const auto end = svg.find('>', pos);
  const auto at = svg.find(" " + name + "=\"", pos);
  if (at == std::string::npos || at > end) return {};
  const auto begin = at + name.size() + 3;
  return svg.substr(begin, svg.find('"', begin) - begin);
}

// The value of attribute `name` of the first <element ...> (std::regex would overflow the stack
// on a path with thousands of points).
inline std::string attribute(const std::string& svg, const std::string& element, const std::string& name) {
  for (auto pos = svg.find("<" + element); pos != std::string::npos; pos = svg.find("<" + element, pos + 1)) {
    const char after = svg[pos + 1 + element.size()];
    if (after != ' ' && after != '>' && after != '/') continue;
    return attribute_at(svg, pos, name);
  }
  return {};
}

// The numbers in a text such as a path's d or an animation's values: path commands and
// separators count as spaces.
inline std::vector<double> numbers_in(const std::string& text) {
  std::string cleaned = text;
  for (char& c : cleaned)
    if (c == 'M' || c == 'L' || c == 'H' || c == 'V' || c == 'Z' || c == ',' || c == ';' || c == '(' || c == ')')
      c = ' ';
  std::vector<double> out;
  std::istringstream in(cleaned);
  for (double v; in >> v;) out.push_back(v);
  return out;
}

// Every start tag closed by its own end tag, in order; self-closing tags, the XML declaration and
// nothing else. Returns "" when well nested, otherwise what is wrong.
inline std::string nesting_error(const std::string& xml) {
  std::vector<std::string> open;
  for (std::size_t pos = xml.find('<'); pos != std::string::npos; pos = xml.find('<', pos + 1)) {
    const std::size_t end = xml.find('>', pos);
    if (end == std::string::npos) return "unterminated tag at " + std::to_string(pos);
    const std::string tag = xml.substr(pos + 1, end - pos - 1);
    if (tag.empty()) return "empty tag";
    if (tag[0] == '?') continue;
    if (tag[0] == '/') {
      const std::string name = tag.substr(1);
      if (open.empty() || open.back() != name)
        return "</" + name + "> closes " + (open.empty() ? "nothing" : open.back());
      open.pop_back();
      continue;
    }
    if (tag.back() == '/') continue;
    open.push_back(tag.substr(0, tag.find_first_of(" \n")));
  }
  return open.empty() ? "" : "<" + open.back() + "> never closed";
}

// What is drawn, without the legend.
inline std::string body_of(const std::string& svg) { return svg.substr(0, svg.find("<g font-size=")); }

// The legend's labels in order, as written (XML-escaped).
inline std::vector<std::string> legend_labels(const std::string& svg) {
  std::vector<std::string> labels;
  const auto legend = svg.find("<g font-size=");
  if (legend == std::string::npos) return labels;
  for (auto pos = svg.find("<text", legend); pos != std::string::npos; pos = svg.find("<text", pos + 1)) {
    const auto begin = svg.find('>', pos) + 1;
    labels.push_back(svg.substr(begin, svg.find("</text>", begin) - begin));
  }
  return labels;
}

// The attributes svg::Drawing writes for a colour, to find what is drawn in it.
inline std::string fill_is(const std::string& colour) { return "fill=\"" + colour + "\""; }
inline std::string stroke_is(const std::string& colour) { return "stroke=\"" + colour + "\""; }

// The circles of the first group of points whose start tag begins with `attributes` (say
// `fill="#2ca02c" stroke="none"`): svg::Drawing::points writes one <g ...> of <circle>s per call.
inline std::size_t dots_in_group(const std::string& svg, const std::string& attributes) {
  const auto group = svg.find("<g " + attributes);
  if (group == std::string::npos) return 0;
  return count(svg.substr(group, svg.find("</g>", group) - group), "<circle");
}

}  // namespace polyplan::test
