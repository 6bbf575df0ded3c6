#pragma once
#include <stdexcept>
#include <string>

namespace polyplan {

// Bad input: a file that cannot be read, or that describes something invalid. The message is
// one line naming the file, the object and what is wrong; programs exit 2 on it.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace polyplan
