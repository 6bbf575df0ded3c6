#pragma once
// The bench programs that time whole runs of polyplan (arm_grid_table, time_limit_table) start
// each run as a child process with this.
#include <unistd.h>

#include <cstdio>
#include <string>
#include <vector>

namespace polyplan::bench {

// Starts the program `args[0]` with `args`, its standard output thrown away, in a child process;
// `before_exec` runs in the child first (to set a resource limit). The child's id.
template <class BeforeExec>
pid_t spawn_quiet(std::vector<std::string> args, BeforeExec before_exec) {
  std::fflush(stdout);  // or the child's freopen writes what this process has buffered once more
  const pid_t child = fork();
  if (child == 0) {
    before_exec();
    if (!freopen("/dev/null", "w", stdout)) _exit(126);
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    _exit(127);
  }
  return child;
}

}  // namespace polyplan::bench
