// polyplan steer --model dubins|reeds-shepp --radius R --from X,Y,THETA --to X,Y,THETA
// [--json FILE|-] [--svg OUT.svg] [--all-words]: the shortest steering curve between two poses
// (theta in degrees), its word and segments, its picture, and every word tried with its length.
#include "cli/command.hpp"
#include "cli/option_flags.hpp"

#include <polyplan/car/dubins.hpp>
#include <polyplan/car/reeds_shepp.hpp>
#include <polyplan/draw/steering_svg.hpp>
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/registry/steering_json.hpp>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>

namespace polyplan::cli {
namespace {

// --model and --radius.
struct Steering {
  enum class Model { dubins, reeds_shepp } model = Model::dubins;
  double radius = 1;
};
OptionTable<Steering> steering_table() {
  OptionTable<Steering> table;
  return table
      .add("model", &Steering::model, "dubins (forward only) or reeds-shepp (may reverse)",
           Choices<Steering::Model>{{"dubins", Steering::Model::dubins}, {"reeds-shepp", Steering::Model::reeds_shepp}})
      .add("radius", &Steering::radius, "turning radius", in_range(1e-100, 1e100));
}

struct SteerOptions {
  std::unique_ptr<CommandOptions<Steering>> steering;
  std::string from, to;
  std::string json, svg;
  bool all_words = false;
};

// "X,Y,THETA" with theta in degrees, reduced exactly.
CarPose pose_option(const std::string& text, const char* option) {
  const std::vector<double> values = comma_numbers(text, std::string(option));
  if (values.size() != 3)
    throw InputError(std::string(option) + " " + text + ": expected X,Y,THETA (theta in degrees)");
  return {values[0], values[1],
          degrees_option(text.substr(text.rfind(',') + 1), std::string(option) + " " + text + ": theta") * M_PI / 180};
}

int run_steer(const SteerOptions& o) {
  const Steering steering = o.steering->parse();
  const double radius = steering.radius;
  const CarPose from = pose_option(o.from, "--from"), to = pose_option(o.to, "--to");
  const SteeringWords words = steering.model == Steering::Model::reeds_shepp ? reeds_shepp_words(from, to, radius)
                                                                             : dubins_words(from, to, radius);
  const SteeringPath& path = words.path;
  if (!o.json.empty()) {
    nlohmann::json document = steering_json(path);
    if (o.all_words) document["words"] = steering_words_json(words);
    write_json(document, o.json);
  }
  const std::string summary =
      steering_summary(steering.model == Steering::Model::reeds_shepp ? "reeds-shepp" : "dubins", path);
  if (!o.svg.empty()) draw_steering(path, from, to, radius, summary).write(o.svg);
  if (o.json != "-") std::cout << summary << '\n' << (o.all_words ? steering_words_text(words) : "");
  return ok;
}

}  // namespace

void add_steer_command(CLI::App& app, Action& run) {
  auto options = std::make_shared<SteerOptions>();
  CLI::App* command =
      app.add_subcommand("steer", "The shortest Dubins or Reeds-Shepp curve between two poses of a car");
  options->steering = std::make_unique<CommandOptions<Steering>>(*command, steering_table());
  command->add_option("--from", options->from, "start pose X,Y,THETA (theta in degrees)")->required();
  command->add_option("--to", options->to, "goal pose X,Y,THETA (theta in degrees)")->required();
  command->add_option("--json", options->json,
                      "write {length, word, segments} as JSON to this file ('-' for standard output)");
  command->add_option("--svg", options->svg, "draw the curve, its turning circles and the two poses");
  command->add_flag("--all-words", options->all_words,
                    "list every word tried with its length or 'infeasible', the shortest marked (JSON: words)");
  command->callback([options, &run] { run = [options] { return run_steer(*options); }; });
}

}  // namespace polyplan::cli
