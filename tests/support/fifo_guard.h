// For tests of readers that must never wait on a FIFO: should the reader still be waiting after
// 30 s, the test fails and opens the FIFO's other end, so that the bug fails the test instead
// of hanging ctest.
#pragma once

#include <fcntl.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <future>
#include <string>

namespace taa::test {

// What `read()` returns, run on a thread of its own while `fifo` may be what it reads.
template <class Read>
auto readWithoutWaitingOn(const std::filesystem::path& fifo, Read read) {
  auto reading = std::async(std::launch::async, read);
  if (reading.wait_for(std::chrono::seconds(30)) != std::future_status::ready) {
    ADD_FAILURE() << fifo << ": the read waits on it";
    const int writer = ::open(fifo.c_str(), O_WRONLY | O_NONBLOCK);  // lets it go on
    if (writer >= 0) ::close(writer);
  }
  return reading.get();
}

}  // namespace taa::test
