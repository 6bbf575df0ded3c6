// The pictures of the families a build leaves out (cmake -DPOLYPLAN_FAMILIES), which
// report_pictures.cpp names with the others: each says why there is none. A problem of such a
// family is refused before it is planned, so these are reached only by drawing one alone.
#include <polyplan/draw/arm_svg.hpp>
#include <polyplan/draw/car_svg.hpp>
#include <polyplan/registry/registry.hpp>

#include <stdexcept>

namespace polyplan {

#if !POLYPLAN_WITH_ARM
svg::Drawing draw_plan(const ArmProblem&, const PlanReport<JointAngles>&, const ArmPictureOptions&) {
  planners<PlanarArm>().require_planners();  // refuses, naming the family
  throw std::logic_error("draw_plan: an arm's picture in a build without the arm");
}
#endif

#if !POLYPLAN_WITH_CAR
svg::Drawing draw_plan(const World&, const std::vector<PlanReport<CarState>>&, const std::vector<std::string>&) {
  planners<SteeredCar>().require_planners();
  throw std::logic_error("draw_plan: a car's picture in a build without the car");
}
#endif

}  // namespace polyplan
