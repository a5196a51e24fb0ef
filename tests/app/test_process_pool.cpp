// The pool of child processes (core/app/process_pool.h): at most its limit at work at once, and a
// child in its first moments, idling as it starts, lets a short job start, never more than twice the
// limit in all.
#include <doctest/doctest.h>

#include <chrono>
#include <thread>

#include "process_pool.h"

using namespace bsim;

namespace {

/// Starts `sleep 30` in the pool for job `job` (each test stops it long before).
void start_sleep(ProcessPool<int>& pool, int job) {
  std::string error;
  REQUIRE_MESSAGE(pool.start(job, {find_program("sleep"), "30"}, ".", "/dev/null", error), error);
}

}  // namespace

TEST_SUITE("process pool") {
  TEST_CASE("without a settling time the pool holds its limit") {
    ProcessPool<int> pool(1);
    CHECK(pool.has_room());
    start_sleep(pool, 1);
    CHECK_FALSE(pool.has_room());
    pool.stop_all([](int) {});
    CHECK(pool.empty());
  }

  TEST_CASE("a child still settling lets another start, up to twice the limit; once at work it counts") {
    // A settling time far longer than the few statements between the starts and the checks.
    ProcessPool<int> pool(1, std::chrono::milliseconds(2500));
    start_sleep(pool, 1);
    CHECK(pool.has_room(true));  // the first is still starting: a short job may start
    CHECK_FALSE(pool.has_room());  // a long one may not
    start_sleep(pool, 2);
    CHECK_FALSE(pool.has_room(true));  // twice the limit
    std::this_thread::sleep_for(std::chrono::milliseconds(2700));
    CHECK_FALSE(pool.has_room(true));  // both at work now
    int stopped = 0;
    pool.stop_all([&](int) { ++stopped; });
    CHECK(stopped == 2);
    CHECK(pool.has_room());
  }

  TEST_CASE("a child stopped on its own hands back its job and frees its place") {
    ProcessPool<int> pool(1);
    start_sleep(pool, 7);
    int job = 0, seen = 0;
    pool.for_each([&](pid_t pid, int j) {
      CHECK(pid > 0);
      job = j;
      ++seen;
    });
    CHECK(seen == 1);
    pid_t pid = 0;
    pool.for_each([&](pid_t p, int) { pid = p; });
    CHECK(pool.stop(pid) == job);
    CHECK(job == 7);
    CHECK(pool.empty());
  }
}
