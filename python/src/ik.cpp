// polyplan.ik: the joint angles that put an arm's hand at a target (polyplan ik), as the dict
// `polyplan ik --json -` prints, and its picture.
#include "exact_values.hpp"
#include "plans.hpp"
#include "problems.hpp"

#include <polyplan/arm/ik_study.hpp>
#include <polyplan/draw/arm_svg.hpp>
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/registry/ik_json.hpp>

#include <nlohmann/json.hpp>

#include <pybind11/pybind11.h>

namespace py = pybind11;

namespace polyplan::python {

void bind_ik(py::module_& m) {
  m.def(
      "ik",
      [](const py::object& arm, const py::object& target, const py::object& orientation, const py::object& all,
         const py::object& collision_free) {
        const std::shared_ptr<ProblemHandle> given = problem_of(arm, "arm");
        if (!given->door().arm()) throw InputError("arm: expected a polyplan.Arm, got a polyplan.World");
        const ExactPoint exact = exact_point(target, "target");
        IkRequest request;
        request.target = {to_double(exact.x), to_double(exact.y)};
        request.exact_target = exact;
        if (!orientation.is_none())
          request.orientation_degrees = to_double(reduce_degrees(exact_number(orientation, "orientation")));
        request.all = flag_of(all, "all");
        request.collision_free = flag_of(collision_free, "collision_free");
        const ArmProblem& problem = *given->door().arm();
        IkStudy study;
        locked(given->lock(), [&] { study = study_ik(problem, request); });
        py::dict result = from_json(ik_json(request, study));
        result["svg"] = draw_ik_study(problem, request, study, "inverse kinematics").str();
        return result;
      },
      py::arg("arm"), py::arg("target"), py::arg("orientation") = py::none(), py::arg("all") = true,
      py::arg("collision_free") = false,
      R"(Joint angles that put the arm's hand at `target` (x, y), as `polyplan ik` finds them: closed form
for two links, and for three with an `orientation` (the last link's absolute angle, degrees,
reduced modulo 360 exactly); damped least squares and FABRIK otherwise; within the arm file's joint
limits. `all`: every distinct solution found, not only the first; `collision_free`: only those
free of the arm file's obstacles. Returns the dict `polyplan ik --json -` prints (target,
orientation, found, solutions: [{angles, error, free}], why_not) and svg, every solution drawn.
Raises InputError for a bad argument.)");
}

}  // namespace polyplan::python
