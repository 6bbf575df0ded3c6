// read_wkt_obstacles (io/wkt_reader.cpp): the shipped WKT file ring by ring, coordinates as the
// exact values of the nearest doubles (docs/design.md), and every way a file can be wrong with its
// exact message (naming the world file, the WKT file and the line).
#include <polyplan/io/wkt_reader.hpp>
#include "world_fixtures.hpp"

#include <gtest/gtest.h>

using namespace polyplan;
using polyplan::test::data_file;
using polyplan::test::input_error_of;
using polyplan::test::pt;
using polyplan::test::write_temp_file;

namespace {

// The message for the WKT file `text`, read for the world file "w.json".
std::string wkt_problem(const std::string& file_name, const std::string& text) {
  const std::string path = write_temp_file(file_name, text);
  return input_error_of([&] { read_wkt_obstacles(path, "w.json"); });
}

std::string prefix(const std::string& file_name) {
  return "w.json: obstacles_wkt \"" + polyplan::test::temp_path(file_name) + "\": ";
}

}  // namespace

TEST(WktReader, ReadsTheShippedMultipolygonAndPolygon) {
  // MULTIPOLYGON(((1 6,4 6,4 9,1 9,1 6)),((5 1,9 1,9 5,5 5,5 1),(6 2,6 4,8 4,8 2,6 2)))
  // POLYGON((2 1.5,4 2.5,2.5 4,2 1.5))
  const auto obstacles = read_wkt_obstacles(data_file("worlds/wkt_obstacles.wkt"), "wkt_obstacles.json");
  ASSERT_EQ(obstacles.size(), 3u);
  // The closing copy of the first vertex is dropped; the order is the file's.
  EXPECT_EQ(obstacles[0].outer, (Ring{pt("1", "6"), pt("4", "6"), pt("4", "9"), pt("1", "9")}));
  EXPECT_TRUE(obstacles[0].holes.empty());
  EXPECT_EQ(obstacles[1].outer, (Ring{pt("5", "1"), pt("9", "1"), pt("9", "5"), pt("5", "5")}));
  ASSERT_EQ(obstacles[1].holes.size(), 1u);
  EXPECT_EQ(obstacles[1].holes[0], (Ring{pt("6", "2"), pt("6", "4"), pt("8", "4"), pt("8", "2")}));
  // 1.5 and 2.5 are doubles exactly.
  EXPECT_EQ(obstacles[2].outer, (Ring{pt("2", "1.5"), pt("4", "2.5"), pt("2.5", "4")}));
  EXPECT_TRUE(obstacles[2].holes.empty());
}

TEST(WktReader, CoordinatesAreTheDoublesExactValues) {
  // A WKT 0.1 is the double nearest 1/10, exactly: 3602879701896397/36028797018963968.
  const std::string path = write_temp_file("tenths.wkt", "POLYGON((0.1 0.1,1 0.1,1 1,0.1 0.1))\n");
  const auto obstacles = read_wkt_obstacles(path, "w.json");
  ASSERT_EQ(obstacles.size(), 1u);
  ASSERT_EQ(obstacles[0].outer.size(), 3u);
  const Rational tenth = obstacles[0].outer[0].x;
  EXPECT_EQ(tenth, Rational(mpz_class("3602879701896397"), mpz_class("36028797018963968")));
  EXPECT_NE(tenth, Rational(1, 10));
  EXPECT_EQ(obstacles[0].outer[1], (ExactPoint{1, tenth}));
}

TEST(WktReader, BlankLinesAreSkippedButCounted) {
  const std::string text = "\n  \nPOLYGON((0 0,1 0,1 1,0 0))\n\nPOLYGON((5 5,6 5,6 6,5 5))\nLINESTRING(0 0,1 1)\n";
  EXPECT_EQ(wkt_problem("counted.wkt", text),
            prefix("counted.wkt") + "line 6: cannot read WKT: expected POLYGON or MULTIPOLYGON, got \"LINESTRING\"");
}

TEST(WktReader, UnknownTypeIsNamed) {
  EXPECT_EQ(wkt_problem("line.wkt", "LINESTRING(0 0,1 1,2 0)\n"),
            prefix("line.wkt") + "line 1: cannot read WKT: expected POLYGON or MULTIPOLYGON, got \"LINESTRING\"");
  EXPECT_EQ(wkt_problem("words.wkt", "this is not WKT\n"),
            prefix("words.wkt") + "line 1: cannot read WKT: expected POLYGON or MULTIPOLYGON, got \"THIS\"");
}

TEST(WktReader, MalformedPolygon) {
  const std::string malformed = "line 1: cannot read WKT: malformed ";
  EXPECT_EQ(wkt_problem("truncated.wkt", "POLYGON((4 4,6 4,6 6,4\n"),
            prefix("truncated.wkt") + malformed + "POLYGON: expected a number, got the end of the file");
  EXPECT_EQ(wkt_problem("letters.wkt", "POLYGON((0 0,a 0,1 1,0 0))\n"),
            prefix("letters.wkt") + malformed + "POLYGON: expected a number, got \"a\"");
  EXPECT_EQ(wkt_problem("multi.wkt", "MULTIPOLYGON(((0 0,1 0,1 1,0 0))\n"),
            prefix("multi.wkt") + malformed + "MULTIPOLYGON: expected ')', got the end of the file");
  EXPECT_EQ(wkt_problem("z.wkt", "POLYGON((0 0 1,1 0 1,1 1 1,0 0 1))\n"),
            prefix("z.wkt") + malformed + "POLYGON: a point has more than two coordinates");
}

TEST(WktReader, EmptyMultipolygonIsMalformed) {
  EXPECT_EQ(wkt_problem("empty_multi.wkt", "MULTIPOLYGON EMPTY\n"),
            prefix("empty_multi.wkt") + "line 1: cannot read WKT: malformed MULTIPOLYGON: EMPTY holds no polygon");
}

// These crashed the process (SIGSEGV) when CGAL's WKT reader read them: it popped the closing
// point of an empty ring.
TEST(WktReader, EmptyRingsAreMalformedNotACrash) {
  const std::string malformed = "line 1: cannot read WKT: malformed ";
  EXPECT_EQ(wkt_problem("empty.wkt", "POLYGON EMPTY\n"),
            prefix("empty.wkt") + malformed + "POLYGON: EMPTY holds no polygon");
  EXPECT_EQ(wkt_problem("empty_ring.wkt", "POLYGON(())\n"),
            prefix("empty_ring.wkt") + malformed + "POLYGON: empty ring");
  EXPECT_EQ(wkt_problem("empty_hole.wkt", "POLYGON((0 0,4 0,4 4,0 0),())\n"),
            prefix("empty_hole.wkt") + malformed + "POLYGON: empty ring");
  EXPECT_EQ(wkt_problem("empty_multi_ring.wkt", "MULTIPOLYGON((()))\n"),
            prefix("empty_multi_ring.wkt") + malformed + "MULTIPOLYGON: empty ring");
}

TEST(WktReader, NotANumberAndInfinityAreRefused) {
  const std::string malformed = "line 1: cannot read WKT: malformed POLYGON: ";
  EXPECT_EQ(wkt_problem("nan.wkt", "POLYGON((0 0,NaN 0,1 1,0 0))\n"),
            prefix("nan.wkt") + malformed + "expected a number, got \"NaN\"");
  EXPECT_EQ(wkt_problem("inf.wkt", "POLYGON((0 0,1 0,1 Inf,0 0))\n"),
            prefix("inf.wkt") + malformed + "expected a number, got \"Inf\"");
  EXPECT_EQ(wkt_problem("minus_inf.wkt", "POLYGON((0 0,1 0,1 -inf,0 0))\n"),
            prefix("minus_inf.wkt") + malformed + "number \"-\": not a number");
  EXPECT_NE(wkt_problem("huge.wkt", "POLYGON((0 0,1e160 0,1 1,0 0))\n")
                .find("malformed POLYGON: number \"1e160\": overflows the supported range"),
            std::string::npos);
}

TEST(WktReader, AGeometryMaySpanLines) {
  const std::string path = write_temp_file("lines.wkt", "POLYGON(\n (0 0, 1 0,\n  1 1, 0 0)\n)\n");
  ASSERT_EQ(read_wkt_obstacles(path, "w.json").size(), 1u);
  EXPECT_EQ(wkt_problem("late.wkt", "POLYGON((0 0,1 0,1 1,0 0))\n\nPOLYGON(\n(0 0,\nx 1))\n"),
            prefix("late.wkt") + "line 3: cannot read WKT: malformed POLYGON: expected a number, got \"x\"");
}

TEST(WktReader, MissingFile) {
  const std::string path = std::string(POLYPLAN_SOURCE_DIR) + "/data/worlds/does_not_exist.wkt";
  EXPECT_EQ(input_error_of([&] { read_wkt_obstacles(path, "w.json"); }),
            "w.json: obstacles_wkt \"" + path + "\": cannot open file");
}

TEST(WktReader, FileOfBlankLinesHoldsNoPolygon) {
  EXPECT_EQ(wkt_problem("blank.wkt", "\n   \n\t\n"),
            prefix("blank.wkt") + "cannot read WKT: the file holds no POLYGON or MULTIPOLYGON");
  EXPECT_EQ(wkt_problem("nothing.wkt", ""),
            prefix("nothing.wkt") + "cannot read WKT: the file holds no POLYGON or MULTIPOLYGON");
}

TEST(WktReader, KeywordsAreCaseInsensitive) {
  const std::string path =
      write_temp_file("lower_case.wkt", "polygon((0 0,1 0,1 1,0 0))\nMultiPolygon(((5 5,6 5,6 6,5 5)))\n");
  EXPECT_EQ(read_wkt_obstacles(path, "w.json").size(), 2u);
}
