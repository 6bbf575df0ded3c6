// read_scenarios and read_reference_lengths (io/movingai_scenario.cpp): the shipped arena files
// field by field (against the file's lines counted here), and the exact message for each
// malformed line or file.
#include <polyplan/io/movingai_scenario.hpp>
#include "world_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

using namespace polyplan;
using polyplan::test::data_file;
using polyplan::test::input_error_of;
using polyplan::test::write_temp_file;

namespace {

// Lines that hold something, after the first: the queries, counted without the library.
std::size_t query_lines(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  std::size_t n = 0;
  while (std::getline(in, line)) n += line.find_first_not_of(" \t\r") != std::string::npos;
  return n;
}

// The message for `text` read by `read` from a file `name`, after "<its path>: ".
template <class Read>
std::string problem_with(const std::string& name, const std::string& text, Read read) {
  const std::string path = write_temp_file(name, text);
  const std::string message = input_error_of([&] { read(path); });
  return message.rfind(path + ": ", 0) == 0 ? message.substr(path.size() + 2) : "not naming the file: " + message;
}

std::string scenario_problem(const std::string& name, const std::string& text) {
  return problem_with(name, text, read_scenarios);
}

// The reference file `text` for a scenario file of `queries` queries.
std::string reference_problem(const std::string& name, const std::string& text, std::size_t queries = 4) {
  return problem_with(name, text, [&](const std::string& path) { return read_reference_lengths(path, queries); });
}

}  // namespace

TEST(MovingAIScenario, ReadsTheArenaScenarios) {
  const std::string path = data_file("movingai/scenarios/arena.map.scen");
  const auto queries = read_scenarios(path);
  ASSERT_EQ(queries.size(), 160u);
  EXPECT_EQ(queries.size(), query_lines(path));
  // "0	maps/dao/arena.map	49	49	1	11	1	12	1"
  const ScenarioQuery& first = queries.front();
  EXPECT_EQ(first.bucket, 0);
  EXPECT_EQ(first.map_width, 49);
  EXPECT_EQ(first.map_height, 49);
  EXPECT_EQ(first.start_x, 1);
  EXPECT_EQ(first.start_y, 11);
  EXPECT_EQ(first.goal_x, 1);
  EXPECT_EQ(first.goal_y, 12);
  EXPECT_EQ(first.octile_text, "1");
  EXPECT_EQ(first.octile_length, 1.0);
  EXPECT_EQ(first.line, 2);
  // "0	maps/dao/arena.map	49	49	1	13	4	12	3.41421": the length keeps its printed
  // digits.
  EXPECT_EQ(queries[2].octile_text, "3.41421");
  EXPECT_EQ(queries[2].octile_length, 3.41421);
  // "15	maps/dao/arena.map	49	49	1	7	47	46	62.1543", the last line.
  const ScenarioQuery& last = queries.back();
  EXPECT_EQ(last.bucket, 15);
  EXPECT_EQ(last.start_x, 1);
  EXPECT_EQ(last.start_y, 7);
  EXPECT_EQ(last.goal_x, 47);
  EXPECT_EQ(last.goal_y, 46);
  EXPECT_EQ(last.octile_length, 62.1543);
  EXPECT_EQ(last.line, 161);
  // Ten queries a bucket, one a line, all on the 49 × 49 map.
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const ScenarioQuery& q = queries[i];
    EXPECT_EQ(q.bucket, static_cast<int>(i / 10)) << i;
    EXPECT_EQ(q.line, static_cast<int>(i + 2)) << i;
    EXPECT_TRUE(q.map_width == 49 && q.map_height == 49) << i;
    for (const int c : {q.start_x, q.start_y, q.goal_x, q.goal_y}) EXPECT_TRUE(c >= 0 && c < 49) << i;
  }
}

TEST(MovingAIScenario, ReadsTheArenaReferenceLengths) {
  const auto lengths = read_reference_lengths(data_file("movingai/reference/arena.csv"), 160);
  ASSERT_EQ(lengths.size(), 160u);
  EXPECT_EQ(lengths[0], 1.0);
  EXPECT_EQ(lengths[1], 2.0);
  EXPECT_EQ(lengths[2], 3.16227766016838);
  EXPECT_EQ(lengths[159], 60.45305689631398);
  // A shortest path is no shorter than the straight line between its ends; query 2, from (1, 13)
  // to (4, 12), is that line.
  const auto queries = read_scenarios(data_file("movingai/scenarios/arena.map.scen"));
  ASSERT_EQ(queries.size(), lengths.size());
  for (std::size_t i = 0; i < lengths.size(); ++i) {
    ASSERT_TRUE(lengths[i]) << i;
    const double straight = std::hypot(queries[i].goal_x - queries[i].start_x, queries[i].goal_y - queries[i].start_y);
    EXPECT_GE(*lengths[i], straight - 1e-12) << i;
  }
  EXPECT_NEAR(*lengths[2], std::sqrt(10.0), 1e-14);
}

TEST(MovingAIScenario, BlankLinesAreSkippedButCounted) {
  const std::string path =
      write_temp_file("blank_lines.scen", "version 1\n\n \t\n0\tm.map\t4\t4\t0\t0\t3\t3\t4.24264\n");
  const auto queries = read_scenarios(path);
  ASSERT_EQ(queries.size(), 1u);
  EXPECT_EQ(queries[0].line, 4);
  EXPECT_EQ(queries[0].goal_x, 3);
  EXPECT_EQ(queries[0].octile_length, 4.24264);
  EXPECT_TRUE(read_scenarios(write_temp_file("no_queries.scen", "version 1\n")).empty());
}

TEST(MovingAIScenario, MalformedFiles) {
  const std::string path = data_file("movingai/scenarios/does_not_exist.scen");
  EXPECT_EQ(input_error_of([&] { read_scenarios(path); }), path + ": cannot open file");
  EXPECT_EQ(scenario_problem("empty.scen", ""), "line 1: expected 'version 1' (a MovingAI scenario file)");
  EXPECT_EQ(scenario_problem("a_map.scen", "type octile\nheight 4\n"),
            "line 1: expected 'version 1' (a MovingAI scenario file)");
}

TEST(MovingAIScenario, MalformedLines) {
  const std::string fields = "line 3: expected 'bucket map width height start_x start_y goal_x goal_y length'";
  EXPECT_EQ(scenario_problem("eight_fields.scen",
                             "version 1\n0\tm.map\t4\t4\t0\t0\t3\t3\t4.24264\n0\tm.map\t4\t4\t0\t0\t3\t3\n"),
            fields);
  EXPECT_EQ(scenario_problem("word_for_number.scen",
                             "version 1\n0\tm.map\t4\t4\t0\t0\t3\t3\t4.24264\n0\tm.map\t4\tfour\t0\t0\t3\t3\t4.2\n"),
            fields);
  EXPECT_EQ(scenario_problem("length_word.scen", "version 1\n0\tm.map\t4\t4\t0\t0\t3\t3\tlong\n"),
            "line 2: length is not a number: long");
  EXPECT_EQ(scenario_problem("length_partial.scen", "version 1\n0\tm.map\t4\t4\t0\t0\t3\t3\t4.2x\n"),
            "line 2: length is not a number: 4.2x");
  EXPECT_EQ(scenario_problem("length_nan.scen", "version 1\n0\tm.map\t4\t4\t0\t0\t3\t3\tnan\n"),
            "line 2: length is not a number: nan");
  EXPECT_EQ(scenario_problem("ten_fields.scen", "version 1\n0\tm.map\t4\t4\t0\t0\t3\t3\t4.2\t7\n"),
            "line 2: expected 'bucket map width height start_x start_y goal_x goal_y length'");
}

TEST(MovingAIScenario, QueriesMustFitTheMap) {
  const auto queries = read_scenarios(write_temp_file("fit.scen",
                                                      "version 1\n0\tm.map\t4\t3\t0\t0\t3\t2\t4.2\n"
                                                      "0\tm.map\t4\t3\t0\t0\t4\t2\t4.2\n"));
  EXPECT_EQ(input_error_of([&] { check_scenarios_match(queries, 4, 3, "m.map", "fit.scen"); }),
            "fit.scen: line 3: goal (4, 2) is outside the 4x3 map");
  EXPECT_EQ(input_error_of([&] { check_scenarios_match({queries[0]}, 5, 3, "m.map", "fit.scen"); }),
            "fit.scen: line 2: the query is for a 4x3 map, m.map is 5x3");
  const auto negative =
      read_scenarios(write_temp_file("negative.scen", "version 1\n0\tm.map\t4\t3\t-1\t0\t3\t2\t4.2\n"));
  EXPECT_EQ(input_error_of([&] { check_scenarios_match(negative, 4, 3, "m.map", "negative.scen"); }),
            "negative.scen: line 2: start (-1, 0) is outside the 4x3 map");
}

TEST(MovingAIReference, GapsAreMissingAndMinusOneIsNoPath) {
  const auto lengths = read_reference_lengths(write_temp_file("gaps.csv", "index,length\n0,1.5\n\n3,-1\n"), 5);
  ASSERT_EQ(lengths.size(), 5u);
  EXPECT_EQ(lengths[0], 1.5);
  EXPECT_FALSE(lengths[1]);
  EXPECT_FALSE(lengths[2]);
  EXPECT_EQ(lengths[3], -1.0);
  EXPECT_FALSE(lengths[4]);
}

TEST(MovingAIReference, MalformedLinesAndFiles) {
  const std::string path = data_file("movingai/reference/does_not_exist.csv");
  EXPECT_EQ(input_error_of([&] { read_reference_lengths(path, 1); }), path + ": cannot open file");
  EXPECT_EQ(reference_problem("length_word.csv", "index,length\n0,1\n1,far\n"),
            "line 3: expected 'index,length', got \"1,far\"");
  EXPECT_EQ(reference_problem("index_word.csv", "index,length\nfirst,1\n"),
            "line 2: expected 'index,length', got \"first,1\"");
  EXPECT_EQ(reference_problem("no_comma.csv", "index,length\nnot a length\n"),
            "line 2: expected 'index,length', got \"not a length\"");
  EXPECT_EQ(reference_problem("partial.csv", "index,length\n0,1x\n"), "line 2: expected 'index,length', got \"0,1x\"");
  EXPECT_EQ(reference_problem("no_header.csv", "0,1\n"),
            "line 1: expected the header 'index,length' (a reference-lengths file)");
}

// "-1" was read by std::stoul as the largest unsigned long: resize(index + 1) wrapped to 0 and
// the length was written far out of bounds (a crash). 3·10^8 allocated 4.7 GB for a 30-byte file.
TEST(MovingAIReference, AnIndexOutsideTheScenarioFileIsAnError) {
  EXPECT_EQ(reference_problem("negative_index.csv", "index,length\n-1,5\n"),
            "line 2: expected 'index,length', got \"-1,5\"");
  EXPECT_EQ(reference_problem("largest_index.csv", "index,length\n18446744073709551615,5\n"),
            "line 2: index 18446744073709551615 is beyond the scenario file's 4 queries");
  EXPECT_EQ(reference_problem("too_large_index.csv", "index,length\n18446744073709551616,5\n"),
            "line 2: expected 'index,length', got \"18446744073709551616,5\"");
  EXPECT_EQ(reference_problem("far_index.csv", "index,length\n300000000,5\n"),
            "line 2: index 300000000 is beyond the scenario file's 4 queries");
  EXPECT_EQ(reference_problem("next_index.csv", "index,length\n4,5\n"),
            "line 2: index 4 is beyond the scenario file's 4 queries");
}
