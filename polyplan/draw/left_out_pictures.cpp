// The pictures of the families a build leaves out (cmake -DPOLYPLAN_FAMILIES), which
// report_pictures.cpp names with the others: each says why there is none. A problem of such a
// family is refused before it is planned, so these are reached only by drawing one alone.
#include <polyplan/draw/arm_svg.hpp>
#include <polyplan/draw/car_svg.hpp>
#include <polyplan/geometry/input_error.hpp>

namespace polyplan {

#if !POLYPLAN_WITH_ARM
svg::Drawing draw_plan(const ArmProblem&, const PlanReport<JointAngles>&, const ArmPictureOptions&) {
  throw InputError(
      "no picture of an arm: this polyplan is built without the arm (cmake -DPOLYPLAN_FAMILIES=arm or all)");
}
#endif

#if !POLYPLAN_WITH_CAR
svg::Drawing draw_plan(const World&, const std::vector<PlanReport<CarState>>&, const std::vector<std::string>&) {
  throw InputError(
      "no picture of a car: this polyplan is built without the car (cmake -DPOLYPLAN_FAMILIES=car or all)");
}
#endif

}  // namespace polyplan
