#pragma once
// Reading a whole input file, and echoing its text in messages, within limits::file_bytes: every reader of polyplan
// goes through here, so /dev/zero or a directory given as a file ends at once with a one-line message. Not installed.
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/geometry/input_limits.hpp>

#include <filesystem>
#include <fstream>
#include <string>

namespace polyplan::detail {

// Shortens text that a message echoes (a key, a value, a line) to a readable length: a message
// stays one line even when the input holds a 20 MB key.
inline std::string abbreviated_text(const std::string& s, std::size_t most = 40) {
  return s.size() > most ? s.substr(0, most - 3) + "..." : s;
}

// The file's whole text; InputError "<path>: <why>" when it cannot be opened, is a directory or
// is larger than limits::file_bytes. `name` is how messages call the file (default: its path).
inline std::string read_text_file(const std::string& path, const std::string& name = "") {
  const std::string& called = name.empty() ? path : name;
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(called + ": is a directory, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(called + ": cannot open file");
  std::string text;
  char buffer[1 << 16];
  // Read in blocks and stop one byte past the limit: a device or a pipe has no size to ask for.
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (text.size() > limits::file_bytes)
      throw InputError(called + ": larger than the supported " + std::to_string(limits::file_bytes >> 20) + " MiB");
  }
  if (in.bad()) throw InputError(called + ": cannot read file");
  return text;
}

}  // namespace polyplan::detail
