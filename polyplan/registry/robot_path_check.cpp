#include <polyplan/registry/robot_path_check.hpp>

#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/io/world_reader.hpp>
#if POLYPLAN_WITH_CAR
#include <polyplan/car/car_path_check.hpp>
#include <polyplan/io/car_path_reader.hpp>
#endif

namespace polyplan {

PathCheck check_path_file(const World& world, const std::string& path_file) {
  if (world.robot.car) {
#if POLYPLAN_WITH_CAR
    return check_car_path(world, read_car_path(path_file));
#else
    throw InputError(world.source +
                     ": a car's path is checked by the car planners' library, which this polyplan is "
                     "built without (cmake -DPOLYPLAN_FAMILIES=car or all)");
#endif
  }
  const CSpace cspace(world);
  return check_path(cspace, read_path(path_file));
}

}  // namespace polyplan
