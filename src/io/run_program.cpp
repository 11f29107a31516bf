#include "sandflow/io/run_program.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

extern char** environ;

namespace sf::io {
namespace {

std::string failure(const std::string& what) {
  return what + ": " + std::strerror(errno);
}

// The input as a file in memory, not a pipe: the program may read all, some
// or none of it, and no write of ours waits on it or dies of SIGPIPE.
int inputFile(const std::string& input, std::string& why) {
  const int fd = ::memfd_create("sandflow-input", MFD_CLOEXEC);
  if (fd < 0) {
    why = failure("couldn't create input file");
    return -1;
  }
  for (std::size_t done = 0; done < input.size();) {
    const ssize_t w = ::write(fd, input.data() + done, input.size() - done);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) {
      why = failure("couldn't write input file");
      ::close(fd);
      return -1;
    }
    done += std::size_t(w);
  }
  if (::lseek(fd, 0, SEEK_SET) != 0) {
    why = failure("couldn't rewind input file");
    ::close(fd);
    return -1;
  }
  return fd;
}

}  // namespace

ProgramRun runProgram(const std::vector<std::string>& args, const std::string& input) {
  ProgramRun run;
  const int in = inputFile(input, run.output);
  if (in < 0) return run;
  int out[2];
  if (::pipe2(out, O_CLOEXEC) != 0) {
    run.output = failure("couldn't create pipe");
    ::close(in);
    return run;
  }
  std::vector<std::string> words = args;
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, in, 0);
  posix_spawn_file_actions_adddup2(&actions, out[1], 1);
  posix_spawn_file_actions_adddup2(&actions, out[1], 2);
  pid_t child = -1;
  const int rc = posix_spawn(&child, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(in);
  ::close(out[1]);
  if (rc != 0) {
    ::close(out[0]);
    run.output = "couldn't execute \"" + args[0] + "\": " + std::strerror(rc);
    return run;
  }
  char buffer[4096];
  for (;;) {
    const ssize_t n = ::read(out[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    run.output.append(buffer, std::size_t(n));
  }
  ::close(out[0]);
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  // Worded as Tcl's exec words it, which this replaces.
  if (!run.output.empty() && run.output.back() == '\n') run.output.pop_back();
  run.ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  if (!run.ok) {
    if (!run.output.empty()) run.output += '\n';
    run.output += WIFSIGNALED(status)
                      ? std::string("child killed: ") + ::strsignal(WTERMSIG(status))
                      : std::string("child process exited abnormally");
  }
  return run;
}

}  // namespace sf::io
