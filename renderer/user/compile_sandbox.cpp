#include "user/compile_sandbox.h"

#include <fcntl.h>
#include <poll.h>
#include <pthread.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <mutex>
#include <new>

// Under AddressSanitizer the process has reserved terabytes of shadow memory, so an
// address-space limit would fail the sanitizer's own allocations: the memory bound is left
// to the CPU bound there (sanitized builds are CI's, never a user's).
#if defined(__SANITIZE_ADDRESS__)
#define TAA_SANDBOX_NO_AS_LIMIT 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(memory_sanitizer) || \
    __has_feature(thread_sanitizer)
#define TAA_SANDBOX_NO_AS_LIMIT 1
#endif
#endif

namespace taa::user {

namespace {

// The first byte the child sends: how `work` ended.
constexpr char kSandboxDone = 'D', kSandboxNoMemory = 'M', kSandboxThrew = 'X';

struct SandboxJob {
  const std::function<std::string()>* work;
  char status = kSandboxThrew;
  std::string output;
};

void* sandboxThread(void* arg) {
  auto* job = static_cast<SandboxJob*>(arg);
  try {
    job->output = (*job->work)();
    job->status = kSandboxDone;
  } catch (const std::bad_alloc&) {
    job->status = kSandboxNoMemory;
  } catch (const std::exception& e) {
    job->output = e.what();
    job->status = kSandboxThrew;
  } catch (...) {
    job->status = kSandboxThrew;
  }
  return nullptr;
}

#ifndef TAA_SANDBOX_NO_AS_LIMIT
// The child's virtual size now: the limit is set on top of it, since the child inherits
// every mapping of the parent (a Vulkan driver's, a loaded scene's).
uint64_t sandboxVirtualBytes() {
  std::ifstream statm("/proc/self/statm");
  uint64_t pages = 0;
  statm >> pages;
  return pages * uint64_t(sysconf(_SC_PAGESIZE));
}
#endif

bool sandboxWriteAll(int fd, const char* data, size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    data += n;
    size -= size_t(n);
  }
  return true;
}

// The child's state for sandboxCpuBudget: the pipe, the reply the SIGXCPU handler writes
// (prepared beforehand: a handler may only write and exit) and the phase's CPU timer.
int gSandboxFd = -1;
std::string* gSandboxBudgetReply = nullptr;
timer_t gSandboxPhaseTimer{};
bool gSandboxPhaseTimerMade = false;

void sandboxBudgetHandler(int) {
  if (gSandboxBudgetReply) {
    const std::string& r = *gSandboxBudgetReply;
    sandboxWriteAll(gSandboxFd, r.data(), r.size());
    _exit(0);
  }
  _exit(4);
}

// Arms the phase timer `ms` of the child's CPU time (all its threads) from now; 0 disarms it.
// A CPU-clock timer, not RLIMIT_CPU: the limit counts whole seconds, so a phase of 3 s
// stopped anywhere up to 4 s.
// Without a timer (timer_create failed) a phase has only the whole's limit, which ends it too.
void sandboxArmPhase(long ms) {
  if (!gSandboxPhaseTimerMade) {
    sigevent ev{};
    ev.sigev_notify = SIGEV_SIGNAL;
    ev.sigev_signo = SIGXCPU;
    if (timer_create(CLOCK_PROCESS_CPUTIME_ID, &ev, &gSandboxPhaseTimer) != 0) return;
    gSandboxPhaseTimerMade = true;
  }
  itimerspec t{};
  t.it_value.tv_sec = ms / 1000;
  t.it_value.tv_nsec = (ms % 1000) * 1000000L;
  timer_settime(gSandboxPhaseTimer, 0, &t, nullptr);
}

[[noreturn]] void sandboxChild(int fd, const std::function<std::string()>& work,
                               const SandboxLimits& limits) {
  gSandboxFd = fd;
  const rlimit core{0, 0};
  setrlimit(RLIMIT_CORE, &core);
  const rlimit cpu{rlim_t(limits.cpuSeconds), rlim_t(limits.cpuSeconds + 1)};
  setrlimit(RLIMIT_CPU, &cpu);
#ifndef TAA_SANDBOX_NO_AS_LIMIT
  const uint64_t as = sandboxVirtualBytes() + limits.memoryBytes + limits.stackBytes;
  const rlimit mem{rlim_t(as), rlim_t(as)};
  setrlimit(RLIMIT_AS, &mem);
#endif
  SandboxJob job{&work};
  pthread_attr_t attr;
  pthread_attr_init(&attr);
  pthread_attr_setstacksize(&attr, size_t(limits.stackBytes));
  pthread_t thread;
  if (pthread_create(&thread, &attr, &sandboxThread, &job) != 0) _exit(3);
  pthread_join(thread, nullptr);
  const char status = job.status;
  const bool ok = sandboxWriteAll(fd, &status, 1) &&
                  sandboxWriteAll(fd, job.output.data(), job.output.size());
  _exit(ok ? 0 : 3);
}

std::mutex& sandboxMutex() {
  static std::mutex m;
  return m;
}

}  // namespace

void sandboxCpuBudget(std::chrono::milliseconds budget, const std::string& result) {
  if (gSandboxFd < 0) return;  // not in a sandbox's child
  if (result.empty()) {
    sandboxArmPhase(0);
    signal(SIGXCPU, SIG_DFL);
    return;
  }
  static std::string reply;
  reply = std::string(1, kSandboxDone) + result;
  gSandboxBudgetReply = &reply;
  signal(SIGXCPU, &sandboxBudgetHandler);
  sandboxArmPhase(std::max<long>(1, long(budget.count())));
}

SandboxOutcome runSandboxed(const std::function<std::string()>& work, const SandboxLimits& limits,
                            const std::function<void()>& inParent) {
  std::lock_guard<std::mutex> lock(sandboxMutex());
  if (inParent) inParent();
  SandboxOutcome out;
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) {
    out.detail = std::string("pipe: ") + std::strerror(errno);
    return out;
  }
  std::fflush(nullptr);  // nothing buffered is written twice by the child
  const pid_t pid = ::fork();
  if (pid < 0) {
    out.detail = std::string("fork: ") + std::strerror(errno);
    ::close(fds[0]);
    ::close(fds[1]);
    return out;
  }
  if (pid == 0) {
    ::close(fds[0]);
    sandboxChild(fds[1], work, limits);
  }
  ::close(fds[1]);
  const auto deadline =
      std::chrono::steady_clock::now() + std::chrono::seconds(limits.wallSeconds);
  std::string received;
  bool killed = false, tooMuch = false;
  char buf[65536];
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
                          deadline - std::chrono::steady_clock::now())
                          .count();
    if (left <= 0) {
      killed = true;
      break;
    }
    pollfd p{fds[0], POLLIN, 0};
    const int r = ::poll(&p, 1, int(left));
    if (r < 0 && errno == EINTR) continue;
    if (r == 0) continue;  // the deadline check above ends the loop
    const ssize_t n = ::read(fds[0], buf, sizeof(buf));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    received.append(buf, size_t(n));
    if (received.size() > limits.maxOutputBytes + 1) {
      tooMuch = true;
      break;
    }
  }
  if (killed || tooMuch) ::kill(pid, SIGKILL);
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (killed) {
    out.end = SandboxEnd::OverTime;
  } else if (tooMuch) {
    out.end = SandboxEnd::OverMemory;
  } else if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    // The kernel sends SIGXCPU at the soft CPU limit and SIGKILL at the hard one.
    out.end = sig == SIGXCPU || sig == SIGKILL ? SandboxEnd::OverTime : SandboxEnd::Crashed;
    out.signal = sig;
  } else if (WIFEXITED(status) && WEXITSTATUS(status) == 0 && !received.empty()) {
    const char s = received[0];
    out.output = received.substr(1);
    out.end = s == kSandboxDone ? SandboxEnd::Done
              : s == kSandboxNoMemory ? SandboxEnd::OverMemory
                                      : SandboxEnd::Crashed;
  } else {
    out.end = SandboxEnd::Crashed;
  }
  return out;
}

std::string describeSandboxEnd(const SandboxOutcome& o, const SandboxLimits& limits) {
  switch (o.end) {
    case SandboxEnd::Done:
      return "done";
    case SandboxEnd::OverTime:
      return "more than " + std::to_string(limits.cpuSeconds) + " s of CPU (or " +
             std::to_string(limits.wallSeconds) + " s of wall time)";
    case SandboxEnd::OverMemory:
      return "more than " + std::to_string(limits.memoryBytes >> 20) + " MiB of memory";
    case SandboxEnd::Crashed:
      if (o.signal != 0)
        return "a crash (signal " + std::to_string(o.signal) + ", " + strsignal(o.signal) + ")";
      return o.output.empty() ? std::string("a crash") : "an error: " + o.output;
    case SandboxEnd::Unavailable:
      return "no child process (" + o.detail + ")";
  }
  return "?";
}

}  // namespace taa::user
