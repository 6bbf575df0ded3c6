#pragma once
// What every libFuzzer target of polyplan does: hands the fuzzer's bytes, as text, to one reader
// entry point that the program uses. An InputError is the right answer to a bad file; anything
// else (a crash, a sanitizer report, another exception, a hang past -timeout, memory past
// -rss_limit_mb) is a bug, which libFuzzer reports with the input that caused it.
#include <polyplan/geometry/input_error.hpp>

#include <cstddef>
#include <cstdint>
#include <string>

namespace polyplan::fuzz {

template <class Read>
int read_text(const std::uint8_t* data, std::size_t size, Read read) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    read(text);
  } catch (const InputError&) {
  }
  return 0;
}

}  // namespace polyplan::fuzz
