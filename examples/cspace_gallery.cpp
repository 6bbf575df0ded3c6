// An SVG of the C-space of every world in a folder (default: data/worlds), and a line each.
// Usage: cspace_gallery [WORLDS_DIR] [OUT_DIR]
// Exit code 2 when a world could not be read or drawn (the others are still drawn).
#include <polyplan/draw/world_svg.hpp>
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/io/world_reader.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <string>
#include <system_error>
#include <vector>

#ifndef POLYPLAN_DATA_DIR
#define POLYPLAN_DATA_DIR "data"
#endif

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  if (argc > 3 || (argc > 1 && (std::string(argv[1]) == "-h" || std::string(argv[1]) == "--help"))) {
    std::cerr << "usage: cspace_gallery [WORLDS_DIR] [OUT_DIR]\n"
                 "  draws OUT_DIR/<name>.svg for every WORLDS_DIR/<name>.json (default: "
              << POLYPLAN_DATA_DIR "/worlds and .)\n";
    return argc > 3 ? 2 : 0;
  }
  const fs::path worlds = argc > 1 ? fs::path(argv[1]) : fs::path(POLYPLAN_DATA_DIR "/worlds");
  const fs::path out = argc > 2 ? fs::path(argv[2]) : fs::path(".");

  std::vector<fs::path> files;
  std::error_code error;
  for (fs::directory_iterator it(worlds, error), end; !error && it != end; it.increment(error)) {
    if (it->path().extension() == ".json") files.push_back(it->path());
  }
  if (error) {
    std::cerr << "cspace_gallery: cannot list " << worlds.string() << ": " << error.message() << '\n';
    return 2;
  }
  fs::create_directories(out, error);
  if (error) {
    std::cerr << "cspace_gallery: cannot create " << out.string() << ": " << error.message() << '\n';
    return 2;
  }
  std::sort(files.begin(), files.end());

  int failures = 0;
  std::printf("%-24s %7s %12s %16s %9s\n", "world", "solids", "C-obstacles", "free components", "seconds");
  for (const fs::path& file : files) {
    const std::string name = file.stem().string();
    try {
      const polyplan::World world = polyplan::read_world(file.string());
      if (!polyplan::round_features(world).empty()) {  // discs or walls: a polygon C-space cannot hold them
        std::printf("%-24s (discs or walls: no polygon C-space; polyplan check checks paths among them)\n",
                    name.c_str());
        continue;
      }
      const auto started = std::chrono::steady_clock::now();
      const polyplan::CSpace cspace(world);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
      const fs::path picture = out / (name + ".svg");
      polyplan::write_cspace_svg(cspace, picture.string());
      std::printf("%-24s %7zu %12zu %16zu %9.3f  -> %s\n", name.c_str(), cspace.solids().size(),
                  cspace.cobstacles().size(), cspace.free_components().size(), seconds, picture.string().c_str());
    } catch (const polyplan::InputError& e) {
      std::fflush(stdout);
      std::cerr << e.what() << '\n';
      ++failures;
    } catch (const std::exception& e) {  // e.g. the picture could not be written
      std::fflush(stdout);
      std::cerr << name << ": " << e.what() << '\n';
      ++failures;
    }
    std::fflush(stdout);
  }
  if (files.empty()) std::cerr << "cspace_gallery: no .json files in " << worlds.string() << '\n';
  return failures ? 2 : 0;
}
