// libFuzzer target: the MovingAI scenario reader, as scen and grid read SCEN.scen.
#include "fuzz_reader.hpp"

#include <polyplan/io/movingai_scenario.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return polyplan::fuzz::read_text(data, size,
                                   [](const std::string& text) { polyplan::parse_scenarios(text, "fuzz.scen"); });
}
