// World, Arm and CSpace in Python: reading them, what they hold, and the exact checks.
#include "problems.hpp"

#include "exact_values.hpp"

#include <polyplan/arm/arm.hpp>
#include <polyplan/draw/round_cspace_svg.hpp>
#include <polyplan/geometry/path_check.hpp>
#include <polyplan/geometry/round_cspace_area.hpp>
#include <polyplan/geometry/round_world_check.hpp>
#include <polyplan/io/arm_reader.hpp>
#include <polyplan/io/world_reader.hpp>

#include <pybind11/stl.h>

namespace polyplan::python {
namespace {

using WorldPtr = std::shared_ptr<WorldHandle>;
using ArmPtr = std::shared_ptr<ArmHandle>;

// Reader warnings (unknown keys) as Python warnings, as the program prints them on stderr.
void warn(const std::vector<std::string>& warnings) {
  for (const std::string& w : warnings)
    if (PyErr_WarnEx(PyExc_UserWarning, w.c_str(), 1) != 0) throw py::error_already_set();  // warnings made errors
}

// A problem made by `read` (a reader that lists its warnings), the warnings raised in Python.
template <class Handle, class Read>
std::shared_ptr<Handle> read_warning(Read read) {
  std::vector<std::string> warnings;
  auto handle = std::make_shared<Handle>(read(&warnings));
  warn(warnings);
  return handle;
}

py::list rings(const std::vector<PolygonWithHoles>& polygons) {
  py::list out;
  for (const PolygonWithHoles& p : polygons) out.append(points_array(p.outer));
  return out;
}

// (xmin, ymin, xmax, ymax) as Fractions, or None.
py::object box_tuple(const std::optional<Bounds>& box) {
  if (!box) return py::none();
  return py::make_tuple(fraction(box->xmin), fraction(box->ymin), fraction(box->xmax), fraction(box->ymax));
}

py::tuple query_tuple(const Query& q) {
  const auto pose = [](const ExactPoint& p, const std::optional<double>& theta) {
    return theta ? py::make_tuple(fraction(p.x), fraction(p.y), *theta) : py::make_tuple(fraction(p.x), fraction(p.y));
  };
  return py::make_tuple(q.name, pose(q.start, q.start_theta), pose(q.goal, q.goal_theta));
}

// The C-space of a world as Python sees it: read-only views, computed when asked.
struct CSpaceView {
  WorldPtr world;
};

py::object free_components(const CSpaceView& view) {
  const py::object FreeComponent = py::module_::import("polyplan").attr("FreeComponent");
  py::list out;
  const auto& components = locked(view.world->lock(), [&]() -> const std::vector<polyplan::FreeComponent>& {
    return view.world->cspace().free_components();
  });
  for (const polyplan::FreeComponent& c : components) {
    py::list holes;
    for (const Ring& h : c.holes) holes.append(points_array(h));
    out.append(FreeComponent(c.outer.empty() ? py::object(py::none()) : py::object(points_array(c.outer)), holes,
                             c.area ? fraction(*c.area) : py::object(py::none())));
  }
  return out;
}

py::object free_area(const CSpaceView& view) {
  Rational sum = 0;
  const auto& components = locked(view.world->lock(), [&]() -> const std::vector<polyplan::FreeComponent>& {
    return view.world->cspace().free_components();
  });
  for (const polyplan::FreeComponent& c : components) {
    if (!c.area) return py::none();
    sum += *c.area;
  }
  return fraction(sum);
}

// The C-space of a world with discs or walls: cores grown by radii (geometry/round_cspace.hpp), and
// its free area, computed once.
struct RoundCSpaceView {
  WorldPtr world;
  FreeArea area;
};

const RoundCSpace& round_space(const RoundCSpaceView& view) {
  return locked(view.world->lock(), [&]() -> const RoundCSpace& { return view.world->door().round_world().cspace(); });
}

// The names of RoundCore::Kind and RoundCSpace::Robot, in their enumerations' order.
constexpr const char* kind_names[] = {"point", "wall", "polygon"};
constexpr const char* robot_names[] = {"point", "disc", "polygon"};

py::list round_cores(const RoundCSpaceView& view) {
  const py::object RoundCore = py::module_::import("polyplan").attr("RoundCore");
  py::list out;
  for (const polyplan::RoundCore& core : round_space(view).obstacles) {
    py::list holes;
    for (std::size_t i = 1; i < core.rings.size(); ++i) holes.append(points_array(core.rings[i]));
    out.append(RoundCore(kind_names[static_cast<int>(core.kind)],
                         points_array(core.rings.empty() ? core.points : core.rings.front()), holes,
                         fraction(core.radius), core.name));
  }
  return out;
}

void bind_round_cspace(py::module_& m) {
  py::class_<RoundCSpaceView>(m, "RoundCSpace",
                              "The C-space of a world with discs or walls (polyplan.cspace(world)): C-obstacles as "
                              "cores grown by radii, and the free area, exact or certified.")
      .def_property_readonly(
          "robot", [](const RoundCSpaceView& v) { return robot_names[static_cast<int>(round_space(v).robot)]; },
          "\"point\", \"disc\" or \"polygon\".")
      .def_property_readonly("obstacles", &round_cores,
                             "The C-obstacles as RoundCore(kind, points, holes, radius, name): the points within "
                             "radius (a Fraction) of the core, a \"point\" (points: its centre), a \"wall\" (its "
                             "polyline; radius 0: crossed never, touched freely) or a \"polygon\" (its outer ring, "
                             "holes its holes); points as (N, 2) float64 arrays.")
      .def_property_readonly(
          "box", [](const RoundCSpaceView& v) { return box_tuple(round_space(v).box); },
          "The box the reference point keeps to, (xmin, ymin, xmax, ymax) as Fractions; None without box bounds.")
      .def_property_readonly(
          "disc",
          [](const RoundCSpaceView& v) -> py::object {
            const auto& disc = round_space(v).disc;
            return disc ? py::make_tuple(fraction(disc->center.x), fraction(disc->center.y), fraction(disc->radius))
                        : py::object(py::none());
          },
          "The disc the reference point keeps to in disc bounds, (x, y, radius) as Fractions; else None.")
      .def_property_readonly(
          "free_area",
          [](const RoundCSpaceView& v) { return v.area.exact ? fraction(*v.area.exact) : py::object(py::none()); },
          "The free area as an exact Fraction when it is rational (every radius 0, box bounds); else None.")
      .def_property_readonly(
          "free_area_bounds", [](const RoundCSpaceView& v) { return py::make_tuple(v.area.lower, v.area.upper); },
          "(lower, upper): floats that hold the free area for sure (inf, inf when unbounded).")
      .def(
          "svg",
          [](const RoundCSpaceView& v) {
            return locked(v.world->lock(), [&] {
              return round_cspace_picture(v.world->world(), v.world->door().round_world().cspace()).str();
            });
          },
          "The picture `polyplan cspace WORLD --svg` draws, as SVG text.")
      .def("__repr__", [](const RoundCSpaceView& v) {
        return "<polyplan.RoundCSpace of " + v.world->world().source + ": free area " + free_area_text(v.area) + ">";
      });
}

}  // namespace

std::shared_ptr<ProblemHandle> problem_of(py::handle value, const std::string& what) {
  if (py::isinstance<WorldHandle>(value)) return value.cast<WorldPtr>();
  if (py::isinstance<ArmHandle>(value)) return value.cast<ArmPtr>();
  throw InputError(what + ": expected a polyplan.World or a polyplan.Arm, got " + type_name(value));
}

std::shared_ptr<WorldHandle> world_of(py::handle value, const std::string& what) {
  if (!py::isinstance<WorldHandle>(value))
    throw InputError(what + ": expected a polyplan.World, got " + type_name(value));
  return value.cast<WorldPtr>();
}

void bind_problems(py::module_& m) {
  py::class_<WorldHandle, WorldPtr>(m, "World", R"(A polygon world: obstacles, bounds, a robot and queries, all exact.

Read one with polyplan.read_world(path), World.from_json(text) or World.from_dict(d) (the
world file's format, docs/design.md "World file"). Coordinates are exact rationals: an int, a
fractions.Fraction or a decimal string ("0.1" is exactly 1/10) is its exact value; a float is
the exact value of that double (0.1 is 3602879701896397/36028797018963968).)")
      .def_static(
          "from_json",
          [](const py::object& text, const py::object& name) {
            return read_warning<WorldHandle>([&](auto* warnings) {
              return parse_world(text_of(text, "World.from_json: text"), text_of(name, "World.from_json: name"),
                                 warnings);
            });
          },
          py::arg("text"), py::arg("name") = "<json>",
          "The world in a world file's JSON text; `name` stands for the file in messages and relative paths.")
      .def_property_readonly(
          "source", [](const WorldHandle& w) { return w.world().source; }, "The file (or name) it was read from.")
      .def_property_readonly(
          "bounds", [](const WorldHandle& w) { return box_tuple(w.world().bounds); },
          "(xmin, ymin, xmax, ymax) as Fractions, or None for an unbounded world.")
      .def_property_readonly(
          "obstacles", [](const WorldHandle& w) { return rings(w.world().obstacles); },
          "Each obstacle's outer boundary, an (N, 2) float64 array (counter-clockwise).")
      .def_property_readonly(
          "robot",
          [](const WorldHandle& w) {
            py::list parts;
            for (const Ring& r : w.world().robot.parts) parts.append(points_array(r));
            return parts;
          },
          "The robot's parts in its own frame, (N, 2) arrays; empty for a point robot.")
      .def_property_readonly(
          "car",
          [](const WorldHandle& w) -> py::object {
            const auto& car = w.world().robot.car;
            if (!car) return py::none();
            py::dict out;
            out["turning_radius"] = car->turning_radius;
            out["reverse"] = car->reverse;
            return out;
          },
          "When the robot steers like a car: {\"turning_radius\": R, \"reverse\": bool} (the car planners plan for "
          "it); else None.")
      .def_property_readonly(
          "discs",
          [](const WorldHandle& w) {
            std::vector<std::vector<double>> rows;
            for (const Disc& d : w.world().discs)
              rows.push_back({to_double(d.center.x), to_double(d.center.y), to_double(d.radius)});
            return rows_array(rows, 3);
          },
          "The disc obstacles, an (N, 3) float64 array of rows (x, y, radius).")
      .def_property_readonly(
          "walls",
          [](const WorldHandle& w) {
            py::list out;
            for (const Wall& wall : w.world().walls) out.append(points_array(wall));
            return out;
          },
          "The walls of zero thickness, each an (N, 2) float64 array of its polyline's points.")
      .def_property_readonly(
          "disc_bounds",
          [](const WorldHandle& w) -> py::object {
            const auto& d = w.world().disc_bounds;
            if (!d) return py::none();
            return py::make_tuple(fraction(d->center.x), fraction(d->center.y), fraction(d->radius));
          },
          "Bounds that are a disc, (x, y, radius) as Fractions (the free space inside it), or None.")
      .def_property_readonly(
          "robot_disc",
          [](const WorldHandle& w) -> py::object {
            return w.world().robot.disc ? fraction(*w.world().robot.disc) : py::none();
          },
          "A disc robot's radius as a Fraction (its `robot` is then empty), or None.")
      .def_property_readonly(
          "queries",
          [](const WorldHandle& w) {
            py::list out;
            for (const Query& q : w.world().queries) out.append(query_tuple(q));
            return out;
          },
          "The world's queries as (name, start, goal); start and goal are (x, y) Fractions, or (x, y, theta) with "
          "theta in degrees.")
      .def("__repr__", [](const WorldHandle& w) {
        const World& world = w.world();
        std::string round;  // discs, walls, disc bounds (the disc robot is named with the robot)
        for (const std::string& f : round_features(world))
          if (f != "a disc robot") round += f + ", ";
        return "<polyplan.World " + world.source + ": " + std::to_string(world.obstacles.size()) + " obstacle(s), " +
               round +
               (world.robot.disc         ? "disc robot of radius " + to_string(*world.robot.disc)
                : world.robot.is_point() ? std::string("point robot")
                                         : std::to_string(world.robot.parts.size()) + "-part robot") +
               (world.robot.car ? std::string(world.robot.car->reverse ? " (a Reeds–Shepp car)" : " (a Dubins car)")
                                : std::string()) +
               ", " + std::to_string(world.queries.size()) + " query(ies)>";
      });

  py::class_<ArmHandle, ArmPtr>(m, "Arm",
                                R"(A planar n-link arm among obstacle polygons and points (docs/design.md "Arm file").

Read one with polyplan.read_arm(path), Arm.from_json(text) or Arm.from_dict(d). Joint angles
are radians, relative (theta1 from +x, theta_i from link i-1).)")
      .def_static(
          "from_json",
          [](const py::object& text, const py::object& name) {
            return read_warning<ArmHandle>([&](auto* warnings) {
              return parse_arm_problem(text_of(text, "Arm.from_json: text"), text_of(name, "Arm.from_json: name"),
                                       warnings);
            });
          },
          py::arg("text"), py::arg("name") = "<json>",
          "The arm in an arm file's JSON text; `name` stands for the file in messages.")
      .def_property_readonly(
          "source", [](const ArmHandle& a) { return a.problem().source; }, "The file (or name) it was read from.")
      .def_property_readonly(
          "links", [](const ArmHandle& a) { return a.problem().arm.links; }, "The link lengths, base first.")
      .def_property_readonly(
          "joints", [](const ArmHandle& a) { return a.problem().arm.joints(); }, "The number of joints (= links).")
      .def_property_readonly(
          "link_width", [](const ArmHandle& a) { return a.problem().arm.link_width; },
          "0: links are segments; w > 0: each link is a w-wide rectangle.")
      .def_property_readonly(
          "obstacles", [](const ArmHandle& a) { return rings(a.problem().obstacles); },
          "Each obstacle polygon's outer boundary, an (N, 2) float64 array.")
      .def_property_readonly(
          "points",
          [](const ArmHandle& a) {
            std::vector<std::vector<double>> rows;
            for (const auto& p : a.problem().points) rows.push_back({p.x(), p.y()});
            return rows_array(rows, 2);
          },
          "The point obstacles, an (N, 2) float64 array.")
      .def_property_readonly(
          "limits",
          [](const ArmHandle& a) -> py::object {
            if (a.problem().arm.limits.empty()) return py::none();
            py::list out;
            for (const auto& [lo, hi] : a.problem().arm.limits) out.append(py::make_tuple(lo, hi));
            return out;
          },
          "Each joint's limits (lo, hi) in radians, read round the circle, which inverse kinematics keeps to; None "
          "without.")
      .def_property_readonly(
          "queries",
          [](const ArmHandle& a) {
            py::list out;
            for (const ArmQuery& q : a.problem().queries) {
              if (!q.goal_point) {
                out.append(py::make_tuple(q.name, q.start, q.goal));
                continue;
              }
              py::dict goal;
              goal["point"] = py::make_tuple(q.goal_point->point.x(), q.goal_point->point.y());
              goal["orientation"] =
                  q.goal_point->orientation ? py::object(py::float_(*q.goal_point->orientation)) : py::none();
              out.append(py::make_tuple(q.name, q.start, goal));
            }
            return out;
          },
          "The arm's queries as (name, start angles, goal): the goal angles, or for a goal in the workspace\n"
          "{\"point\": (x, y), \"orientation\": radians or None} (the hand at that point).")
      .def(
          "joint_positions",
          [](const ArmHandle& a, const py::object& angles) {
            const JointAngles q = finite_numbers(angles, "angles");
            if (q.size() != a.problem().arm.joints())
              throw InputError("angles: expected " + std::to_string(a.problem().arm.joints()) + " joint angles, got " +
                               std::to_string(q.size()));
            std::vector<std::vector<double>> rows;
            for (const auto& p : polyplan::joint_positions(a.problem().arm, q)) rows.push_back({p.x(), p.y()});
            return rows_array(rows, 2);
          },
          py::arg("angles"),
          "The base, every joint and the tip at these joint angles: a (joints + 1, 2) float64 array.")
      .def("__repr__", [](const ArmHandle& a) {
        const ArmProblem& p = a.problem();
        return "<polyplan.Arm " + p.source + ": " + std::to_string(p.arm.joints()) + " link(s), " +
               std::to_string(p.obstacles.size()) + " obstacle(s), " + std::to_string(p.points.size()) + " point(s), " +
               std::to_string(p.queries.size()) + " query(ies)>";
      });

  m.def(
      "read_world",
      [](const py::object& path) {
        return read_warning<WorldHandle>(
            [&](auto* warnings) { return read_world(path_of(path, "read_world: path"), warnings); });
      },
      py::arg("path"),
      "The world file at `path` (JSON). Raises InputError naming the file and the object for bad input.");
  m.def(
      "read_arm",
      [](const py::object& path) {
        return read_warning<ArmHandle>(
            [&](auto* warnings) { return read_arm_problem(path_of(path, "read_arm: path"), warnings); });
      },
      py::arg("path"),
      "The arm file at `path` (JSON). Raises InputError naming the file and the object for bad input.");

  py::class_<CSpaceView>(
      m, "CSpace", "A world's exact configuration space (polyplan.cspace(world)): the C-obstacles and the free space.")
      .def_property_readonly(
          "obstacles",
          [](const CSpaceView& v) {
            return rings(locked(
                v.world->lock(), [&]() -> const auto& { return v.world->cspace().cobstacles(); }));
          },
          "Each C-obstacle's outer boundary (the obstacles grown by the reflected robot, merged), an (N, 2) float64 "
          "array.")
      .def_property_readonly(
          "free_components", &free_components,
          "The free space's connected components: FreeComponent(outer, holes, area), outer None and area "
          "None for an unbounded one; area an exact Fraction.")
      .def_property_readonly("free_area", &free_area,
                             "The free space's exact area (a Fraction); None when it is unbounded.")
      .def("__repr__", [](const CSpaceView& v) { return "<polyplan.CSpace of " + v.world->world().source + ">"; });

  bind_round_cspace(m);
  m.def(
      "cspace",
      [](const py::object& given) -> py::object {
        const WorldPtr world = world_of(given, "cspace");
        if (!round_features(world->world()).empty()) {
          const FreeArea area = locked(world->lock(), [&] {
            return round_free_area(world->door().round_world().cspace(), world->world().source);
          });
          return py::cast(RoundCSpaceView{world, area});
        }
        locked(world->lock(), [&] { return &world->cspace(); });
        return py::cast(CSpaceView{world});
      },
      py::arg("world"),
      "The world's exact C-space (built once per World, shared by its planners): a CSpace, or a RoundCSpace for a "
      "world with discs or walls.");
}

}  // namespace polyplan::python
