#include <polyplan/io/car_path_reader.hpp>

#include <polyplan/geometry/rational.hpp>
#include <polyplan/io/detail/exact_json.hpp>
#include <polyplan/io/detail/text_file.hpp>

#include <nlohmann/json.hpp>

#include <cmath>

namespace polyplan {
namespace {

using json = nlohmann::json;

constexpr const char* kFormat =
    "a car's path is its segments, {\"segments\": [{\"start\": [x, y, theta], \"steer\": \"L\"|\"S\"|\"R\", \"gear\": "
    "1|-1, \"length\": L}, ...]}, as plan --json writes them";

class Reader : public detail::JsonFileReader {
 public:
  using JsonFileReader::JsonFileReader;
  // A number as its text gives it (floating-point literals are kept as text: parse_exact_json), to
  // the nearest double, within the supported range.
  double number(const json& v, const std::string& object) const {
    if (v.is_number_integer()) return v.get<double>();
    std::string why = "expected a number";
    const auto x = v.is_string() ? parse_rational(v.get<std::string>(), &why) : std::nullopt;
    if (!x) fail(object, why + ", got " + detail::abbreviated_text(v.dump()));
    return to_double(*x);
  }
  CarPathSegment segment(const json& v, const std::string& object) const {
    if (!v.is_object()) fail(object, std::string("expected an object: ") + kFormat);
    for (const char* key : {"start", "steer", "gear", "length"})
      if (!v.contains(key)) fail(object, std::string("missing field \"") + key + "\"");
    const json& start = v["start"];
    if (!start.is_array() || start.size() != 3) fail(object + ".start", "expected a pose [x, y, theta] (degrees)");
    CarPathSegment s;
    s.start = {number(start[0], object + ".start[0]"), number(start[1], object + ".start[1]"),
               number(start[2], object + ".start[2]") * M_PI / 180};
    const json& steer = v["steer"];
    if (!steer.is_string() || (steer != "L" && steer != "S" && steer != "R"))
      fail(object + ".steer", "expected \"L\", \"S\" or \"R\"");
    s.segment.steer = static_cast<Steer>(steer.get<std::string>()[0]);
    const json& gear = v["gear"];
    if (!gear.is_number_integer() || (gear != 1 && gear != -1)) fail(object + ".gear", "expected 1 or -1");
    s.segment.gear = gear.get<int>();
    s.segment.length = number(v["length"], object + ".length");
    if (!(s.segment.length > 0)) fail(object + ".length", "expected a length > 0");
    return s;
  }
};

}  // namespace

std::vector<CarPathSegment> parse_car_path(const std::string& text, const std::string& name) {
  const Reader r(name);
  const json root = r.parse(text);
  if (!root.is_object()) r.fail("car path", std::string("expected an object: ") + kFormat);
  if (!root.contains("segments"))
    r.fail("car path", root.contains("path") ? std::string(kFormat) + "; a list of points would slide the car sideways"
                                             : std::string("missing field \"segments\": ") + kFormat);
  const json& segments = root["segments"];
  if (!segments.is_array() || segments.empty()) r.fail("segments", "expected a non-empty list of segments");
  std::vector<CarPathSegment> path;
  for (std::size_t i = 0; i < segments.size(); ++i)
    path.push_back(r.segment(segments[i], "segments[" + std::to_string(i) + "]"));
  return path;
}

std::vector<CarPathSegment> read_car_path(const std::string& path) {
  return parse_car_path(detail::read_text_file(path), path);
}

}  // namespace polyplan
