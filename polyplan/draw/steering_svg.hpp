#pragma once
// The picture of one steering curve (polyplan steer): the path from start to goal, forward
// stretches and reverse stretches in two colours, the four turning circles of the start and the
// goal, and the two poses as arrows.
#include <polyplan/car/steering_path.hpp>
#include <polyplan/draw/svg.hpp>

#include <string>

namespace polyplan {

// `title` is written at the top (e.g. "reeds-shepp L+S+R-: 12.3").
svg::Drawing draw_steering(const SteeringPath& path, const CarPose& from, const CarPose& to, double radius,
                           const std::string& title);

}  // namespace polyplan
