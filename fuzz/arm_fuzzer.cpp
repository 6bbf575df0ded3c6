// libFuzzer target: the arm reader, as polyplan arm reads ARM.json.
#include "fuzz_reader.hpp"

#include <polyplan/io/arm_reader.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return polyplan::fuzz::read_text(data, size,
                                   [](const std::string& text) { polyplan::parse_arm_problem(text, "fuzz.json"); });
}
