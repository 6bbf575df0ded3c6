#pragma once
// What the conformance tests of the registries iterate over: the shipped data files of a folder
// and the names a registry holds.
#include <polyplan/roadmaps/registry.hpp>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace polyplan::test {

// The stems of the .json files in data/FOLDER ("maze" for data/worlds/maze.json), sorted.
inline std::vector<std::string> shipped(const std::string& folder) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(POLYPLAN_SOURCE_DIR) + "/data/" + folder))
    if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

template <class Space>
std::vector<std::string> registered_planners() {
  std::vector<std::string> names;
  for (const auto& entry : planners<Space>().entries()) names.push_back(entry.name);
  return names;
}

// A test name from a planner's and a file's names: letters, digits and underscores only.
inline std::string test_name(const std::string& planner, const std::string& file) {
  std::string name = planner + "_on_" + file;
  std::replace_if(name.begin(), name.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
  return name;
}

}  // namespace polyplan::test
