// grainlab: the command line. Each subcommand lives in its own *_command.cpp
// and explains itself with --help. No exception escapes main: bad input exits
// 2, a fault of the run or of the system (a full disk, out of memory) 3, each
// with what, where and how to fix it; and what went to standard output is
// flushed and checked before exiting, so that output lost to a full disk or a
// closed pipe is an error, not a silent exit 0.
#include "apps/command_line.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/wait_policy.h"

#include <fmt/format.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <new>
#include <system_error>

using namespace grainlab;

namespace {

int error(int code, const std::string& what) {
  std::fflush(stdout);
  fmt::print(stderr, "grainlab: {}\n", what);
  return code;
}

// The exit code `rc`, or 3 when standard output could not take what was printed.
int checked_exit(int rc) {
  errno = 0;
  if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
    const int err = errno;
    fmt::print(stderr, "grainlab: error: the output to standard output was lost: {}; {}\n",
               err ? std::strerror(err) : "a write failed", err ? fix_for_write_error(err)
                                                               : "is it a full disk or a closed pipe? Check where "
                                                                 "the output goes and run the command again");
    return rc == 0 ? 3 : rc;
  }
  return rc;
}

int run_command(const apps::CommandLine& command_line) {
  try {
    return command_line.run();
  } catch (const InputError& e) {
    return error(2, fmt::format("error: {}", e.what()));
  } catch (const RunError& e) {
    return error(3, fmt::format("run failed: {}", e.what()));
  } catch (const std::filesystem::filesystem_error& e) {
    const int err = e.code().value();
    const std::string where = e.path1().empty() ? std::string() : fmt::format(" '{}'", excerpt(e.path1().string(), 300));
    return error(is_path_error(err) ? 2 : 3, fmt::format("error: a file system operation on{} failed: {}; {}", where,
                                                         e.code().message(), fix_for_write_error(err)));
  } catch (const std::system_error& e) {  // fmt::print to a full disk, a closed pipe
    return error(3, fmt::format("error: {}; {}", e.what(), fix_for_write_error(e.code().value())));
  } catch (const std::bad_alloc&) {
    return error(3, "error: out of memory; the input is larger than this machine's memory holds (fewer grains, "
                    "faces or a smaller box), or free memory and try again");
  } catch (const std::exception& e) {
    return error(3, fmt::format("internal error: {}; please report it with the command line and its input",
                                excerpt(e.what(), 500)));
  } catch (...) {
    return error(3, "internal error: an unknown exception; please report it with the command line and its input");
  }
}

}  // namespace

int main(int argc, char** argv) {
  use_passive_wait_by_default(argv);
  // Past the file-size limit a write fails with EFBIG and is reported; by default SIGXFSZ would kill silently.
  std::signal(SIGXFSZ, SIG_IGN);
  apps::CommandLine command_line;
  try {
    command_line.app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return checked_exit(command_line.app.exit(e));
  }
  return checked_exit(run_command(command_line));
}
