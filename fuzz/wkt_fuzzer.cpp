// libFuzzer target: the WKT reader, as a world's obstacles_wkt file is read.
#include "fuzz_reader.hpp"

#include <polyplan/io/wkt_reader.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return polyplan::fuzz::read_text(data, size,
                                   [](const std::string& text) { polyplan::parse_wkt_obstacles(text, "fuzz.wkt: "); });
}
