#pragma once
// An independent reader of OMPL's benchmark log format, written from OMPL's
// scripts/ompl_benchmark_statistics.py (readBenchmarkLog) for the tests: it reads a log the way
// the script does, line by line, and fails (throws) where the script would, so that the tests
// check what the script will see without needing the script.
#include <cstddef>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace polyplan::test {

struct OmplLogPlanner {
  std::string name;
  std::vector<std::string> settings;           // the common properties' lines
  std::vector<std::string> columns, types;     // per run property: the script's column and type
  std::vector<std::vector<std::string>> runs;  // values, as many as columns (empty: NULL)
  std::vector<std::string> progress_columns;
  std::vector<std::vector<std::vector<std::string>>> progress;  // per run, per sample, the values
};

struct OmplLog {
  std::string library_version, experiment, host, date, setup;
  std::string seed;
  double time_limit = 0, memory_limit = 0, total_time = 0;
  long runs_per_planner = -1;
  std::map<std::string, std::vector<std::string>> enums;
  std::vector<OmplLogPlanner> planners;
};

namespace detail {

inline std::vector<std::string> words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

// The script's split('; ')[:-1] and split(',')[:-1].
inline std::vector<std::string> split_before_last(const std::string& text, const std::string& separator) {
  std::vector<std::string> parts;
  std::size_t from = 0;
  for (std::size_t at; (at = text.find(separator, from)) != std::string::npos; from = at + separator.size())
    parts.push_back(text.substr(from, at - from));
  return parts;
}

class Lines {
 public:
  explicit Lines(std::istream& in) {
    for (std::string line; std::getline(in, line);) lines_.push_back(line);
  }
  bool more() const { return next_ < lines_.size(); }
  const std::string& peek() const {
    if (!more()) throw std::runtime_error("the log ends early");
    return lines_[next_];
  }
  std::string take() {
    const std::string line = peek();
    ++next_;
    return line;
  }
  // The first word of a line whose last words are `ending` ("is the random seed").
  std::string value_before(const std::string& ending) {
    const std::vector<std::string> w = words(take()), end = words(ending);
    if (w.size() < end.size() + 1) throw std::runtime_error("expected \"N " + ending + "\"");
    for (std::size_t i = 0; i < end.size(); ++i)
      if (w[w.size() - end.size() + i] != end[i]) throw std::runtime_error("expected \"N " + ending + "\"");
    return w.front();
  }
  std::string multiline() {
    if (take().rfind("<<<|", 0) != 0) throw std::runtime_error("expected <<<|");
    std::string value;
    while (peek().rfind("|>>>", 0) != 0) value += take() + "\n";
    take();
    return value;
  }

 private:
  std::vector<std::string> lines_;
  std::size_t next_ = 0;
};

inline std::size_t count(const std::string& text) {
  std::size_t used = 0;
  const unsigned long n = std::stoul(text, &used);
  if (used != text.size()) throw std::runtime_error("not a count: " + text);
  return n;
}

}  // namespace detail

inline OmplLog parse_ompl_log(std::istream& in) {
  detail::Lines lines(in);
  OmplLog log;
  std::vector<std::string> w = detail::words(lines.peek());
  if (w.size() >= 2 && w[1] == "version") {
    log.library_version = w.front() + " " + w.back();
    lines.take();
  }
  w = detail::words(lines.take());
  if (w.empty() || w[0] != "Experiment") throw std::runtime_error("expected Experiment NAME");
  log.experiment = w.back();
  w = detail::words(lines.peek());
  if (w.size() >= 3 && w[w.size() - 2] == "experiment" && w.back() == "properties") {
    lines.take();
    for (std::size_t i = detail::count(w[0]); i > 0; --i) lines.take();
  }
  w = detail::words(lines.take());
  if (w.empty() || w[0] != "Running") throw std::runtime_error("expected Running on HOST");
  log.host = w.back();
  const std::string starting = lines.take();
  if (starting.rfind("Starting", 0) != 0) throw std::runtime_error("expected Starting at DATE");
  log.date = starting.substr(std::string("Starting at ").size());
  log.setup = lines.multiline();
  if (lines.peek().rfind("<<<|", 0) == 0) lines.multiline();  // cpu information
  log.seed = lines.value_before("is the random seed");
  log.time_limit = std::stod(lines.value_before("seconds per run"));
  log.memory_limit = std::stod(lines.value_before("MB per run"));
  w = detail::words(lines.peek());
  if (w.size() >= 4 && w[w.size() - 3] == "runs" && w[w.size() - 2] == "per" && w.back() == "planner") {
    log.runs_per_planner = std::stol(w[0]);
    lines.take();
  }
  log.total_time = std::stod(lines.value_before("seconds spent to collect the data"));
  w = detail::words(lines.peek());
  if (w.size() >= 2 && w[w.size() - 2] == "enum") {
    lines.take();
    for (std::size_t i = detail::count(w[0]); i > 0; --i) {
      std::vector<std::string> fields;
      std::string line = lines.take(), field;
      std::istringstream split(line);
      while (std::getline(split, field, '|')) fields.push_back(field);
      log.enums[fields.at(0)] = std::vector<std::string>(fields.begin() + 1, fields.end());
    }
  }
  const std::size_t planners = detail::count(lines.value_before("planners"));
  for (std::size_t p = 0; p < planners; ++p) {
    OmplLogPlanner planner;
    planner.name = lines.take();
    for (std::size_t i = detail::count(detail::words(lines.take()).at(0)); i > 0; --i)
      planner.settings.push_back(lines.take());
    for (std::size_t i = detail::count(detail::words(lines.take()).at(0)); i > 0; --i) {
      w = detail::words(lines.take());
      if (w.size() < 2) throw std::runtime_error(planner.name + ": a run property without a type");
      std::string column;
      for (std::size_t k = 0; k + 1 < w.size(); ++k) column += (k ? "_" : "") + w[k];
      planner.columns.push_back(column);
      planner.types.push_back(w.back());
    }
    for (std::size_t i = detail::count(detail::words(lines.take()).at(0)); i > 0; --i) {
      planner.runs.push_back(detail::split_before_last(lines.take(), "; "));
      if (planner.runs.back().size() != planner.columns.size())
        throw std::runtime_error(planner.name + ": a run with " + std::to_string(planner.runs.back().size()) +
                                 " values for " + std::to_string(planner.columns.size()) + " properties");
    }
    const std::string next = lines.take();
    if (next != ".") {
      for (std::size_t i = detail::count(detail::words(next).at(0)); i > 0; --i) {
        w = detail::words(lines.take());
        std::string column;
        for (std::size_t k = 0; k + 1 < w.size(); ++k) column += (k ? "_" : "") + w[k];
        planner.progress_columns.push_back(column);
      }
      for (std::size_t i = detail::count(detail::words(lines.take()).at(0)); i > 0; --i) {
        std::vector<std::vector<std::string>> samples;
        for (const std::string& sample : detail::split_before_last(lines.take(), ";")) {
          samples.push_back(detail::split_before_last(sample, ","));
          if (samples.back().size() != planner.progress_columns.size())
            throw std::runtime_error(planner.name + ": a progress sample of the wrong size");
        }
        planner.progress.push_back(samples);
      }
      if (lines.take() != ".") throw std::runtime_error(planner.name + ": expected . after the progress data");
    }
    log.planners.push_back(std::move(planner));
  }
  return log;
}

inline OmplLog read_ompl_log(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  return parse_ompl_log(in);
}

}  // namespace polyplan::test
