// libFuzzer target: the world reader (JSON, exact numbers, validation), as the commands read WORLD.json.
#include "fuzz_reader.hpp"

#include <polyplan/io/world_reader.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return polyplan::fuzz::read_text(data, size,
                                   [](const std::string& text) { polyplan::parse_world(text, "fuzz.json"); });
}
