#pragma once
// The picture of one steering curve (polyplan steer): the path from start to goal, forward
// stretches and reverse stretches in two colours, the four turning circles of the start and the
// goal, and the two poses as arrows.
#include <polyplan/car/steering_path.hpp>
#include <polyplan/draw/svg.hpp>

#include <string>
#include <vector>

namespace polyplan {

// `title` is written at the top (e.g. "reeds-shepp L+S+R-: 12.3").
svg::Drawing draw_steering(const SteeringPath& path, const CarPose& from, const CarPose& to, double radius,
                           const std::string& title);

// The pieces, shared with the car's plan pictures (draw/car_svg.hpp):
// a pose as an arrow `length` long along its heading;
std::vector<svg::Point2> pose_arrow(const CarPose& pose, double length);
// the reference point's track along one segment driven from `from`, fine enough to look round
// (at most 2 degrees of turn per step).
std::vector<svg::Point2> segment_track(const CarPose& from, const SteeringSegment& segment, double radius);

}  // namespace polyplan
