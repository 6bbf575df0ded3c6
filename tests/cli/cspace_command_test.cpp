// polyplan cspace, run as a user runs it: every shipped world, exact areas, the picture, and the
// bad-input corpus (tests/data/bad/): exit 2 with one line naming the file and the problem.
#include "cli_runner.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace {

using namespace polyplan::test;
namespace fs = std::filesystem;

struct BadFile {
  std::string file, expected;
};

std::vector<BadFile> bad_corpus() {
  std::vector<BadFile> corpus;
  std::ifstream in(kSource + "/tests/data/bad/expected.tsv");
  std::string line;
  while (std::getline(in, line)) {
    const auto tab = line.find('\t');
    if (line.empty() || line[0] == '#' || tab == std::string::npos) continue;
    corpus.push_back({line.substr(0, tab), line.substr(tab + 1)});
  }
  return corpus;
}

}  // namespace

TEST(BadInput, CorpusIsLargeEnough) { EXPECT_GE(bad_corpus().size(), 20u); }

// Through cspace and plan alike: the readers and the validation are the same, and nothing a
// user can write may reach exit 3 ("internal error") in either.
TEST(BadInput, EveryFileExitsTwoWithOneLineNamingTheProblem) {
  for (const BadFile& bad : bad_corpus())
    for (const std::string command : {"cspace", "plan"}) {
      SCOPED_TRACE(command + " " + bad.file);
      const CliRun run = run_polyplan(command + " '" + kSource + "/tests/data/bad/" + bad.file + "'");
      EXPECT_EQ(run.exit_code, 2) << run.err;
      EXPECT_EQ(lines(run.err), 1u) << run.err;
      EXPECT_NE(run.err.find(bad.expected), std::string::npos) << "expected \"" << bad.expected << "\" in: " << run.err;
      EXPECT_NE(run.err.find(bad.file), std::string::npos) << "the message should name the file: " << run.err;
    }
}

// Whether a world file has discs, walls, disc bounds or a disc robot: a round world's C-space.
bool has_round_things(const fs::path& file) {
  std::ifstream in(file);
  const auto world = nlohmann::json::parse(in);
  return world.contains("discs") || world.contains("walls") ||
         (world.contains("bounds") && world["bounds"].is_object()) ||
         (world.contains("robot") && world["robot"].contains("disc"));
}

TEST(Cspace, EveryShippedWorldBuilds) {
  std::size_t worlds = 0;
  for (const auto& entry : fs::directory_iterator(kSource + "/data/worlds")) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().string());
    ++worlds;
    const CliRun run = run_polyplan("cspace '" + entry.path().string() + "' --json -");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto summary = nlohmann::json::parse(run.out);
    if (has_round_things(entry.path())) {  // discs or walls: cores grown by radii and the free area
      EXPECT_TRUE(summary.contains("cobstacles") && summary.contains("area_text")) << run.out;
      if (summary["bounded"].get<bool>())
        EXPECT_LE(summary["area_lower"].get<double>(), summary["area_upper"].get<double>());
      continue;
    }
    EXPECT_GE(summary["free_components"].size(), 1u);
    EXPECT_GE(summary["seconds"].get<double>(), 0.0);
  }
  EXPECT_GE(worlds, 7u);
}

TEST(Cspace, ExactFitCorridorSplitsTheFreeSpace) {
  // The exact fit leaves two rooms; one billionth more joins them through the corridor.
  const auto exact = nlohmann::json::parse(run_polyplan("cspace " + world("corridor_exact.json") + " --json -").out);
  const auto wide = nlohmann::json::parse(run_polyplan("cspace " + world("corridor_wide.json") + " --json -").out);
  EXPECT_EQ(exact["free_components"].size(), 2u);
  EXPECT_EQ(wide["free_components"].size(), 1u);
}

TEST(Cspace, AreasAreExactRationals) {
  const auto summary =
      nlohmann::json::parse(run_polyplan("cspace " + world("touching_corners.json") + " --json -").out);
  ASSERT_EQ(summary["free_components"].size(), 2u);
  for (const auto& c : summary["free_components"]) {
    EXPECT_EQ(c["area"], "4");
    EXPECT_EQ(c["area_double"], 4.0);
  }
}

TEST(Cspace, WritesAnSvgAndATable) {
  const fs::path svg = fs::temp_directory_path() / "polyplan_cli_test_office.svg";
  const CliRun run = run_polyplan("cspace " + world("office.json") + " --svg '" + svg.string() + "'");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("free component"), std::string::npos) << run.out;
  EXPECT_NE(slurp(svg).find("<svg"), std::string::npos);
  fs::remove(svg);
}
