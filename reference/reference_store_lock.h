// The lock that lets one process at a time render a store key, among processes on one machine or
// on many hosts sharing the store over a network filesystem (`gibench run --slurm`, `--shard`).
//
// A lock is a directory, <root>/locks/<key>, made with mkdir: atomic on every POSIX filesystem,
// NFS included, where flock and fcntl locks are not dependable. Its holder writes an owner file
// (host, pid) inside and touches it every few seconds while it renders. A lock is stale, and is
// broken by the next process that wants it, when its holder is a process of this host that no
// longer exists, or when its owner file has not been touched for kStaleAfter (a holder on another
// host that died; this assumes the hosts' clocks agree within seconds, as NTP keeps them). Breaking
// renames the directory aside (atomic) before removing it. Two processes judging the same lock
// stale at once may both render: the store's publish step still leaves one whole entry (same
// inputs, same pixels), so the cost of that race is time, never a wrong reference.
#pragma once

#include <chrono>
#include <condition_variable>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace gib::ref {

// How often a holder touches its owner file, and how long untouched makes a lock stale.
inline constexpr std::chrono::seconds kLockHeartbeat{5};
inline constexpr std::chrono::seconds kLockStaleAfter{60};

class StoreKeyLock {
 public:
  // Takes the lock at `lock_dir` when free or stale; nullptr when a live holder has it.
  // Throws gib::InputError when the lock's parent cannot be created (an unwritable store).
  static std::unique_ptr<StoreKeyLock> tryAcquire(const std::filesystem::path& lock_dir);
  ~StoreKeyLock();  // stops the heartbeat and removes the directory
  StoreKeyLock(const StoreKeyLock&) = delete;
  StoreKeyLock& operator=(const StoreKeyLock&) = delete;

  // "host:pid" of the lock's holder as its owner file says; empty when unreadable.
  static std::string holderOf(const std::filesystem::path& lock_dir);

 private:
  explicit StoreKeyLock(std::filesystem::path dir);
  void heartbeat();

  std::filesystem::path dir_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace gib::ref
