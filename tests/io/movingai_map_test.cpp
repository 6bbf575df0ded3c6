// read_movingai_map and world_from_grid (io/movingai_map.cpp): the shipped arena map against its
// characters counted here, the merged solids against the blocked cells (area by the shoelace
// formula, and every cell's centre located in the C-space), small maps written inline, and the
// exact message for each malformed file.
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/io/movingai_map.hpp>
#include "world_fixtures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <string>
#include <vector>

using namespace polyplan;
using polyplan::test::area;
using polyplan::test::canonical;
using polyplan::test::data_file;
using polyplan::test::input_error_of;
using polyplan::test::pt;
using polyplan::test::write_temp_file;

namespace {

// The map's rows as the file has them (after the "map" line), read without the library.
std::vector<std::string> rows_of(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line) && line.rfind("map", 0) != 0) {
  }
  std::vector<std::string> rows;
  while (std::getline(in, line)) rows.push_back(line);
  return rows;
}

std::size_t blocked_cells(const GridMap& map) {
  return static_cast<std::size_t>(std::count(map.blocked.begin(), map.blocked.end(), true));
}

// The solids cover exactly the blocked cells: their areas add up to the number of blocked cells,
// and each cell's centre is blocked in the (point robot's) C-space iff the cell is.
void expect_solids_are_the_blocked_cells(const GridMap& map) {
  const World world = world_from_grid(map);
  Rational total = 0;
  for (const PolygonWithHoles& solid : world.obstacles) total += area(solid);
  EXPECT_EQ(total, Rational(mpz_class(blocked_cells(map))));
  const CSpace cspace(world);
  for (int y = 0; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x) {
      const ExactPoint centre{Rational(2 * x + 1, 2), Rational(2 * y + 1, 2)};
      const Location::Kind expected = map.is_blocked(x, y) ? Location::Kind::blocked : Location::Kind::free;
      EXPECT_EQ(cspace.locate(centre).kind, expected) << "cell (" << x << ", " << y << ")";
    }
}

std::string map_text(int width, int height, const std::string& rows) {
  std::string text = "type octile\nheight ";  // appended: GCC 12 misreads "..." + std::string&& (-Warray-bounds)
  text += std::to_string(height) + "\nwidth " + std::to_string(width) + "\nmap\n" + rows;
  return text;
}

// The message for the map file `text`, after "<its path>: ", which it must start with.
std::string map_problem(const std::string& name, const std::string& text) {
  const std::string path = write_temp_file(name, text);
  const std::string message = input_error_of([&] { read_movingai_map(path); });
  return message.rfind(path + ": ", 0) == 0 ? message.substr(path.size() + 2) : "not naming the file: " + message;
}

// Whether one of the world's obstacles has this outer boundary (from any starting vertex) and
// no holes.
bool has_solid(const World& world, const Ring& outer) {
  return std::any_of(world.obstacles.begin(), world.obstacles.end(), [&](const PolygonWithHoles& o) {
    return o.holes.empty() && canonical(o.outer) == canonical(outer);
  });
}

Ring square(int x, int y, int side = 1) { return {{x, y}, {x + side, y}, {x + side, y + side}, {x, y + side}}; }

}  // namespace

TEST(MovingAIMap, ReadsTheArenaMapCellByCell) {
  const std::string path = data_file("movingai/maps/arena.map");
  const GridMap map = read_movingai_map(path);
  EXPECT_EQ(map.source, path);
  EXPECT_EQ(map.width, 49);
  EXPECT_EQ(map.height, 49);
  const std::vector<std::string> rows = rows_of(path);
  ASSERT_EQ(rows.size(), 49u);
  std::size_t blocked_characters = 0;
  for (int y = 0; y < 49; ++y) {
    ASSERT_EQ(rows[y].size(), 49u);
    for (int x = 0; x < 49; ++x) {
      const bool blocked = std::string("@OTWS").find(rows[y][x]) != std::string::npos;
      blocked_characters += blocked;
      EXPECT_EQ(map.is_blocked(x, y), blocked) << "cell (" << x << ", " << y << ") '" << rows[y][x] << "'";
    }
  }
  EXPECT_EQ(blocked_cells(map), blocked_characters);
  EXPECT_GT(blocked_characters, 49u * 4 - 4);  // at least the border of trees
  EXPECT_LT(blocked_characters, 49u * 49);
}

TEST(MovingAIMap, ArenaWorldIsBoundedByTheMapWithAPointRobot) {
  const GridMap map = read_movingai_map(data_file("movingai/maps/arena.map"));
  const World world = world_from_grid(map);
  ASSERT_TRUE(world.bounds);
  EXPECT_EQ(world.bounds->xmin, 0);
  EXPECT_EQ(world.bounds->ymin, 0);
  EXPECT_EQ(world.bounds->xmax, 49);
  EXPECT_EQ(world.bounds->ymax, 49);
  EXPECT_TRUE(world.robot.is_point());
  EXPECT_TRUE(world.queries.empty());
  EXPECT_EQ(world.source, map.source);
  ASSERT_EQ(world.obstacle_names.size(), world.obstacles.size());
  EXPECT_EQ(world.obstacle_names.front(), "blocked region 0");
  // Merged: far fewer solids than blocked cells, and every vertex a lattice point.
  EXPECT_LT(world.obstacles.size() * 10, blocked_cells(map));
  for (const PolygonWithHoles& solid : world.obstacles) {
    for (const ExactPoint& p : solid.outer) EXPECT_TRUE(p.x.get_den() == 1 && p.y.get_den() == 1) << to_string(p);
    EXPECT_GT(area(solid), 0);  // counter-clockwise outer boundaries, clockwise holes
  }
}

TEST(MovingAIMap, ArenaSolidsAreExactlyTheBlockedCells) {
  expect_solids_are_the_blocked_cells(read_movingai_map(data_file("movingai/maps/arena.map")));
}

// Found by fuzzing (it crashed CGAL's symmetric difference): the enclosed free cell (1, 1)
// touches the free cell (0, 2) at a pinch point, so the traced boundary of the one blocked
// region passes that point twice. It is now cut there into simple loops.
TEST(MovingAIMap, ABoundaryThroughAPinchPointTwiceIsCutIntoSimpleLoops) {
  const GridMap map =
      read_movingai_map(write_temp_file("pinch_twice.map", map_text(4, 5, "@@@@\n@.@@\n.@@.\n@@..\n@@@@\n")));
  expect_solids_are_the_blocked_cells(map);
  // The fuzzer's own input, a mutated den312d.
  expect_solids_are_the_blocked_cells(
      read_movingai_map(std::string(POLYPLAN_SOURCE_DIR) + "/tests/data/fuzz/map-crash-pinch-point-twice.map"));
}

TEST(MovingAIMap, RowsCountUpFromTheFilesFirstRow) {
  // Cell (x, y) is [x, x+1] × [y, y+1] with y the row in the file: the first row is y = 0.
  const GridMap map = read_movingai_map(write_temp_file("rows.map", map_text(3, 2, "@..\n..T\n")));
  EXPECT_TRUE(map.is_blocked(0, 0));
  EXPECT_TRUE(map.is_blocked(2, 1));
  EXPECT_EQ(blocked_cells(map), 2u);
  const World world = world_from_grid(map);
  ASSERT_EQ(world.obstacles.size(), 2u);
  EXPECT_TRUE(has_solid(world, square(0, 0)));
  EXPECT_TRUE(has_solid(world, square(2, 1)));
  expect_solids_are_the_blocked_cells(map);
}

TEST(MovingAIMap, EveryBlockingCharacterBlocks) {
  // '@', 'O', 'T', 'W' and 'S' block; '.' and 'G' do not (anything else is an error, below).
  const GridMap map = read_movingai_map(write_temp_file("characters.map", map_text(7, 1, "@OTWS.G\n")));
  for (int x = 0; x < 7; ++x) EXPECT_EQ(map.is_blocked(x, 0), x < 5) << "column " << x;
  const World world = world_from_grid(map);
  ASSERT_EQ(world.obstacles.size(), 1u);  // one run of five cells, one solid
  EXPECT_EQ(canonical(world.obstacles[0].outer), (Ring{pt("0", "0"), pt("5", "0"), pt("5", "1"), pt("0", "1")}));
}

TEST(MovingAIMap, RingOfBlockedCellsIsASolidWithAHole) {
  const GridMap map = read_movingai_map(write_temp_file("ring.map", map_text(3, 3, "@@@\n@.@\n@@@\n")));
  const World world = world_from_grid(map);
  ASSERT_EQ(world.obstacles.size(), 1u);
  EXPECT_EQ(canonical(world.obstacles[0].outer), canonical(square(0, 0, 3)));
  ASSERT_EQ(world.obstacles[0].holes.size(), 1u);
  Ring hole = world.obstacles[0].holes[0];
  std::reverse(hole.begin(), hole.end());  // clockwise
  EXPECT_EQ(canonical(hole), canonical(square(1, 1)));
  EXPECT_EQ(area(world.obstacles[0]), 8);
  expect_solids_are_the_blocked_cells(map);
}

TEST(MovingAIMap, DiagonalNeighboursTouchAtAPinchPoint) {
  // Blocked (0, 0) and (1, 1) touch at (1, 1): the free cells (1, 0) and (0, 1) are two
  // components of the free space, and (1, 1) is a zero-width place between them.
  const GridMap map = read_movingai_map(write_temp_file("diagonal.map", map_text(2, 2, "@.\n.@\n")));
  expect_solids_are_the_blocked_cells(map);
  const CSpace cspace(world_from_grid(map));
  EXPECT_EQ(cspace.free_components().size(), 2u);
  EXPECT_EQ(cspace.locate(pt("1", "1")).components.size(), 2u);
}

TEST(MovingAIMap, WindowsLineEndingsAreRead) {
  const GridMap map =
      read_movingai_map(write_temp_file("crlf.map", "type octile\r\nheight 2\r\nwidth 2\r\nmap\r\n.@\r\n..\r\n"));
  EXPECT_EQ(map.width, 2);
  EXPECT_EQ(map.height, 2);
  EXPECT_TRUE(map.is_blocked(1, 0));
  EXPECT_EQ(blocked_cells(map), 1u);
}

TEST(MovingAIMap, MissingFile) {
  const std::string path = data_file("movingai/maps/does_not_exist.map");
  EXPECT_EQ(input_error_of([&] { read_movingai_map(path); }), path + ": cannot open file");
}

TEST(MovingAIMap, MalformedHeaders) {
  EXPECT_EQ(map_problem("height_word.map", "type octile\nheight two\nwidth 3\nmap\n...\n...\n"),
            "line 2: expected the header lines 'type', 'height H', 'width W', 'map', got \"height two\"");
  EXPECT_EQ(map_problem("unknown_line.map", "type octile\nheight 1\ndepth 3\nwidth 1\nmap\n.\n"),
            "line 3: expected the header lines 'type', 'height H', 'width W', 'map', got \"depth 3\"");
  EXPECT_EQ(map_problem("no_map_line.map", "type octile\nheight 1\nwidth 1\n"), "line 3: missing the 'map' line");
  const std::string size = "width and height must be positive, with at most 67108864 cells, got ";
  EXPECT_EQ(map_problem("zero_height.map", "type octile\nheight 0\nwidth 3\nmap\n"), "line 4: " + size + "3x0");
  EXPECT_EQ(map_problem("no_width.map", "type octile\nheight 2\nmap\n..\n..\n"), "line 3: " + size + "0x2");
  EXPECT_EQ(map_problem("partial_number.map", "type octile\nheight 1x\nwidth 1\nmap\n.\n"),
            "line 2: expected the header lines 'type', 'height H', 'width W', 'map', got \"height 1x\"");
}

// A 60-byte map whose header said 100000 x 100000 allocated 1.2 GB before it found no rows.
TEST(MovingAIMap, AHugeHeaderIsRefusedBeforeAllocating) {
  const std::string size = "width and height must be positive, with at most 67108864 cells, got ";
  EXPECT_EQ(map_problem("huge.map", "type octile\nheight 100000\nwidth 100000\nmap\n"),
            "line 4: " + size + "100000x100000");
  EXPECT_EQ(map_problem("overflow.map", "type octile\nheight 4294967297\nwidth 4294967297\nmap\n"),
            "line 4: " + size + "4294967297x4294967297");
}

TEST(MovingAIMap, UnknownTerrainIsAnError) {
  EXPECT_EQ(map_problem("unknown.map", map_text(3, 2, "...\n.x.\n")),
            "line 6: row 1, column 1: unknown terrain 'x' (free: . G; blocked: @ O T S W)");
  EXPECT_EQ(map_problem("tab.map", map_text(3, 1, "..\t\n")),
            "line 5: row 0, column 2: unknown terrain 0x09 (free: . G; blocked: @ O T S W)");
}

TEST(MovingAIMap, MalformedRows) {
  EXPECT_EQ(map_problem("short_row.map", map_text(3, 2, "...\n..\n")), "line 6: row 1 has 2 cells, the header says 3");
  EXPECT_EQ(map_problem("long_row.map", map_text(3, 2, "....\n...\n")), "line 5: row 0 has 4 cells, the header says 3");
  EXPECT_EQ(map_problem("missing_row.map", map_text(2, 3, "..\n..\n")),
            "line 6: the map has 2 rows, the header says 3");
  EXPECT_EQ(map_problem("no_rows.map", map_text(2, 1, "")), "line 4: the map has 0 rows, the header says 1");
  EXPECT_EQ(map_problem("extra_row.map", map_text(2, 1, "..\n..\n")), "line 6: more rows than the header's 1");
}
