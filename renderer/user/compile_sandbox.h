// Runs work the harness cannot bound from outside (glslang on a user's shader) in a forked
// child process with a known stack and hard limits on CPU time, memory and wall time. A
// macro bomb, an include bomb or a recursion that overflows glslang's stack then costs
// the harness at most those limits and a message, never a crash or a hang of its own.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <string>

namespace taa::user {

struct SandboxLimits {
  int cpuSeconds = 20;                          // RLIMIT_CPU of the child
  int wallSeconds = 60;                         // killed after this, CPU or not (a loaded machine)
  uint64_t memoryBytes = uint64_t(1) << 30;     // address space on top of what the parent had
  uint64_t stackBytes = uint64_t(64) << 20;     // the thread `work` runs on
  uint64_t maxOutputBytes = uint64_t(64) << 20;  // what the child may send back
};

enum class SandboxEnd { Done, OverTime, OverMemory, Crashed, Unavailable };

struct SandboxOutcome {
  SandboxEnd end = SandboxEnd::Unavailable;
  std::string output;  // `work`'s result when Done
  int signal = 0;      // Crashed: the signal that ended the child
  std::string detail;  // Unavailable: why no child could run (fork, pipe)
};

// Calls `work` in a child process under `limits` and returns what it returned. An exception
// `work` lets out of it is reported as Crashed, std::bad_alloc as OverMemory. Calls are
// serialised: the child is forked while no other sandbox runs. `inParent`, when given, runs in
// this process first, under the same lock: state the child inherits (glslang's built-in tables)
// is then never half made by one thread while another forks its copy.
SandboxOutcome runSandboxed(const std::function<std::string()>& work, const SandboxLimits& limits,
                            const std::function<void()>& inParent = {});

// Inside `work` only: from now on the child may use `budget` more of CPU; past it the child
// ends at once as if `work` had returned `result` (a phase of the work with a tighter budget
// than the whole, such as glslang's preprocessor). An empty `result` ends the phase. The
// whole's limit holds throughout: a phase that outlasts it ends with `result` too.
void sandboxCpuBudget(std::chrono::milliseconds budget, const std::string& result);

// "more than 20 s of CPU", "more than 1024 MiB of memory", "signal 11 (Segmentation fault)".
std::string describeSandboxEnd(const SandboxOutcome& outcome, const SandboxLimits& limits);

}  // namespace taa::user
