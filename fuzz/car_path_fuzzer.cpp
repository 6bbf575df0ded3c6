// libFuzzer target: the car path reader, as polyplan check reads a car's segments.
#include "fuzz_reader.hpp"

#include <polyplan/io/car_path_reader.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return polyplan::fuzz::read_text(data, size,
                                   [](const std::string& text) { polyplan::parse_car_path(text, "fuzz.json"); });
}
