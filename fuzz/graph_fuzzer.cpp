// libFuzzer target: the graph reader, as polyplan search reads the course's graph-search
// homework's vertex list.
#include "fuzz_reader.hpp"

#include <polyplan/io/graph_reader.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return polyplan::fuzz::read_text(data, size,
                                   [](const std::string& text) { polyplan::parse_graph(text, "fuzz.json"); });
}
