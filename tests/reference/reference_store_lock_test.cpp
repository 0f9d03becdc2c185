// The store's cross-process lock (reference/reference_store_lock.h): one holder at a time, and a
// lock whose holder died is broken, whether the holder was on this host or another.
#include "reference/reference_store_lock.h"

#include "common/host_name.h"
#include "support/reference_store_fixtures.h"
#include "support/temp_dir.h"

#include <gtest/gtest.h>

#include <fmt/format.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <memory>
#include <thread>

namespace gib::ref {
namespace {

namespace fs = std::filesystem;

// A lock directory as a holder of `host`/`pid` leaves it, last touched `age` ago.
fs::path plantLock(const fs::path& dir, const std::string& host, long pid,
                   std::chrono::seconds age) {
  test::writeFile(dir / "owner", fmt::format("{} {}\n", host, pid));
  const auto then = fs::file_time_type::clock::now() - age;
  fs::last_write_time(dir / "owner", then);
  fs::last_write_time(dir, then);
  return dir;
}

// The pid of a process that has exited (and been reaped): no process has it now.
long deadPid() {
  const pid_t child = fork();
  if (child == 0) _exit(0);
  int status = 0;
  waitpid(child, &status, 0);
  return long(child);
}

TEST(StoreKeyLock, OneHolderAtATimeAndReleasedOnDestruction) {
  test::TempDir dir;
  const fs::path lock_dir = dir / "locks" / "abc";
  {
    std::unique_ptr<StoreKeyLock> first = StoreKeyLock::tryAcquire(lock_dir);
    ASSERT_NE(first, nullptr);
    EXPECT_EQ(StoreKeyLock::tryAcquire(lock_dir), nullptr) << "a live holder has it";
    EXPECT_EQ(StoreKeyLock::holderOf(lock_dir), fmt::format("{}:{}", hostName(), getpid()));
  }
  EXPECT_FALSE(fs::exists(lock_dir));
  EXPECT_NE(StoreKeyLock::tryAcquire(lock_dir), nullptr);
}

TEST(StoreKeyLock, ALockOfADeadProcessOfThisHostIsBroken) {
  test::TempDir dir;
  const fs::path lock_dir =
      plantLock(dir / "locks" / "abc", hostName(), deadPid(), std::chrono::seconds(0));
  std::unique_ptr<StoreKeyLock> lock = StoreKeyLock::tryAcquire(lock_dir);
  ASSERT_NE(lock, nullptr) << "a killed holder (kill -9) must not block the key forever";
  EXPECT_EQ(StoreKeyLock::holderOf(lock_dir), fmt::format("{}:{}", hostName(), getpid()));
}

TEST(StoreKeyLock, ALockOfAnotherHostIsHeldWhileItsHeartbeatIsFresh) {
  test::TempDir dir;
  const fs::path lock_dir =
      plantLock(dir / "locks" / "abc", "another-host", 1234, kLockStaleAfter / 2);
  EXPECT_EQ(StoreKeyLock::tryAcquire(lock_dir), nullptr);
  EXPECT_EQ(StoreKeyLock::holderOf(lock_dir), "another-host:1234");
}

TEST(StoreKeyLock, ALockOfAnotherHostWithoutHeartbeatIsBroken) {
  test::TempDir dir;
  const fs::path lock_dir = plantLock(dir / "locks" / "abc", "another-host", 1234,
                                      kLockStaleAfter + std::chrono::seconds(30));
  const std::unique_ptr<StoreKeyLock> lock = StoreKeyLock::tryAcquire(lock_dir);
  EXPECT_NE(lock, nullptr);
  // The broken lock's directory was moved aside and removed: only the new lock remains.
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir / "locks")) ++entries;
  EXPECT_EQ(entries, 1u);
}

TEST(StoreKeyLock, TheHolderTouchesItsOwnerFileWhileItHoldsTheLock) {
  test::TempDir dir;
  const fs::path lock_dir = dir / "locks" / "abc";
  std::unique_ptr<StoreKeyLock> lock = StoreKeyLock::tryAcquire(lock_dir);
  ASSERT_NE(lock, nullptr);
  const auto old = fs::file_time_type::clock::now() - std::chrono::hours(1);
  fs::last_write_time(lock_dir / "owner", old);
  std::this_thread::sleep_for(kLockHeartbeat + std::chrono::seconds(1));
  EXPECT_GT(fs::last_write_time(lock_dir / "owner"), old + std::chrono::minutes(59));
}

}  // namespace
}  // namespace gib::ref
