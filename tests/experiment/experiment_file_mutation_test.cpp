// The experiment reader under mutated input, as a fuzzer would try it: the shipped experiment
// files with bytes flipped, inserted, deleted and cut short, each parsed where its problem files
// resolve. The only exception a bad file may raise is InputError with one line naming the file;
// anything else (another exception, a crash, a sanitizer report in the deep run) fails. A
// coverage-guided libFuzzer target would link every planner family (the reader checks each
// planner entry on each problem through the registry), which the fuzz build leaves out.
#include <polyplan/experiment/experiment_file.hpp>
#include <polyplan/geometry/input_error.hpp>

#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <sstream>
#include <string>

namespace polyplan {
namespace {

std::string text_of(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

// One random edit of `text`: a byte replaced by one a JSON reader cares about, inserted, deleted,
// or the text cut short.
std::string mutated(std::string text, std::mt19937_64& random) {
  // JSON's punctuation, digits, the letters of true/false/null, a backslash, a NUL byte, and bytes
  // that are not UTF-8 on their own.
  static const std::string interesting = std::string("{}[]\",:-.0123456789eE/ \\nultrfa") + '\0' + '\xff' + '\xc3';
  const auto pick = [&](std::size_t n) { return static_cast<std::size_t>(random() % n); };
  const char c = interesting[pick(interesting.size())];
  switch (pick(4)) {
    case 0: text[pick(text.size())] = c; break;
    case 1: text.insert(text.begin() + static_cast<long>(pick(text.size() + 1)), c); break;
    case 2: text.erase(pick(text.size()), 1 + pick(8)); break;
    default: text.resize(pick(text.size()));
  }
  return text;
}

TEST(ExperimentFileMutations, EveryMutatedFileIsReadOrRefusedInOneLine) {
  std::mt19937_64 random(44);
  std::size_t read = 0, refused = 0;
  for (const char* name : {"seed001_kprm.json", "seed003_rrt_rrtstar.json"}) {
    const std::string path = std::string(POLYPLAN_SOURCE_DIR) + "/data/experiments/" + name;
    const std::string original = text_of(path);
    ASSERT_FALSE(original.empty()) << path;
    for (int trial = 0; trial < 300; ++trial) {
      std::string text = original;
      for (std::size_t edits = 1 + random() % 3; edits > 0 && !text.empty(); --edits) text = mutated(text, random);
      try {
        parse_experiment(text, path);
        ++read;
      } catch (const InputError& e) {
        ++refused;
        const std::string message = e.what();
        EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
      }
    }
  }
  // Both outcomes happen: a test whose every mutation is refused (or read) tries too little.
  EXPECT_GT(read, 0u);
  EXPECT_GT(refused, 100u);
}

}  // namespace
}  // namespace polyplan
