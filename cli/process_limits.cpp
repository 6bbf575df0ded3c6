#include "cli/process_limits.hpp"

#include <polyplan/plan/planner_options.hpp>

#include <chrono>
#include <string>
#include <thread>

#include <sys/resource.h>
#include <unistd.h>

namespace polyplan::cli {
namespace {

// AddressSanitizer reserves terabytes of shadow memory: a cap on the address space would stop it
// before main.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif

}  // namespace

std::shared_ptr<ProcessLimits> add_process_limits(CLI::App& app) {
  auto limits = std::make_shared<ProcessLimits>();
  const auto number = [](double& value, double low, double high, const char* name) {
    return [&value, low, high, name](const std::string& text) {
      const auto parsed = detail::parse_real_number(text);
      if (!parsed || !(*parsed >= low && *parsed <= high))
        throw CLI::ValidationError(std::string(name) + " " + text + ": expected a number in [" +
                                   detail::show_number(low) + ", " + detail::show_number(high) + "]");
      value = *parsed;
    };
  };
  app.add_option_function<std::string>("--max-memory-mb", number(limits->max_memory_mb, 16, 1e7, "--max-memory-mb"),
                                       "every command: the memory the program may take, MB (default 16384)");
  app.add_option_function<std::string>("--max-seconds", number(limits->max_seconds, 0.001, 1e7, "--max-seconds"),
                                       "every command: the seconds the program may run (default 3600)");
  app.fallthrough();
  return limits;
}

void apply_process_limits(const ProcessLimits& limits) {
  // The watchdog first: its stack must not be refused by the cap.
  static std::string message;  // built now: the watchdog only writes it
  message = "error: stopped after the time limit of " + detail::show_number(limits.max_seconds) +
            " s (every command's --max-seconds; raise it, or give the command's own limit)\n";
  std::thread([seconds = limits.max_seconds] {
    std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
    [[maybe_unused]] const auto written = ::write(2, message.data(), message.size());
    ::_exit(2);
  }).detach();
  if (!kAddressSanitizer) {
    const auto bytes = static_cast<rlim_t>(limits.max_memory_mb * 1024 * 1024);
    const rlimit cap{bytes, bytes};
    setrlimit(RLIMIT_AS, &cap);  // best effort: a lower limit set already stays
  }
}

std::string out_of_memory_message(const ProcessLimits& limits) {
  return "out of memory: the command needed more than it may take (" + detail::show_number(limits.max_memory_mb) +
         " MB, --max-memory-mb, or the system's limit)";
}

}  // namespace polyplan::cli
