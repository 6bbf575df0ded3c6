// libFuzzer target: the MovingAI map reader and its polygon world, as scen and grid read MAP.map.
#include "fuzz_reader.hpp"

#include <polyplan/io/movingai_map.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return polyplan::fuzz::read_text(data, size, [](const std::string& text) {
    polyplan::world_from_grid(polyplan::parse_movingai_map(text, "fuzz.map"));
  });
}
