#include "reference/reference_store_lock.h"

#include "common/host_name.h"
#include "common/input_error.h"

#include <fmt/format.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <random>

namespace gib::ref {

namespace fs = std::filesystem;

namespace {

constexpr const char* kOwnerFile = "owner";

struct Owner {
  std::string host;
  long pid = 0;
};

std::optional<Owner> readOwner(const fs::path& dir) {
  std::ifstream in(dir / kOwnerFile);
  Owner owner;
  if (!(in >> owner.host >> owner.pid)) return std::nullopt;
  return owner;
}

// The lock's age since its holder last showed life: the owner file's mtime, or the directory's
// while the owner file is still being written.
std::chrono::seconds sinceLastHeartbeat(const fs::path& dir) {
  std::error_code ec;
  fs::file_time_type touched = fs::last_write_time(dir / kOwnerFile, ec);
  if (ec) touched = fs::last_write_time(dir, ec);
  if (ec) return std::chrono::seconds(0);  // gone meanwhile: let the caller try again
  return std::chrono::duration_cast<std::chrono::seconds>(fs::file_time_type::clock::now() -
                                                          touched);
}

bool isStale(const fs::path& dir) {
  if (const std::optional<Owner> owner = readOwner(dir))
    if (owner->host == hostName() && owner->pid > 0 && kill(pid_t(owner->pid), 0) != 0 &&
        errno == ESRCH)
      return true;
  return sinceLastHeartbeat(dir) > kLockStaleAfter;
}

// Moves a stale lock aside under a unique name, then removes it; a lock that another process
// moved first is simply gone.
void breakLock(const fs::path& dir) {
  static std::atomic<unsigned> counter{0};
  const fs::path aside =
      dir.parent_path() / fmt::format(".stale-{}-{}-{}-{}", dir.filename().string(), getpid(),
                                      counter.fetch_add(1), std::random_device{}());
  std::error_code ec;
  fs::rename(dir, aside, ec);
  if (!ec) fs::remove_all(aside, ec);
}

}  // namespace

std::unique_ptr<StoreKeyLock> StoreKeyLock::tryAcquire(const fs::path& lock_dir) {
  std::error_code ec;
  fs::create_directories(lock_dir.parent_path(), ec);
  if (ec)
    throw InputError(fmt::format("cannot create '{}' ({}); choose another store with --store DIR",
                                 lock_dir.parent_path().string(), ec.message()));
  for (int attempt = 0; attempt < 2; ++attempt) {
    if (mkdir(lock_dir.c_str(), 0777) == 0) {
      std::unique_ptr<StoreKeyLock> lock(new StoreKeyLock(lock_dir));
      return lock;
    }
    if (errno != EEXIST)
      throw InputError(
          fmt::format("cannot create the lock '{}' ({}); choose another store with "
                      "--store DIR",
                      lock_dir.string(), std::strerror(errno)));
    if (!isStale(lock_dir)) return nullptr;
    breakLock(lock_dir);
  }
  return nullptr;
}

StoreKeyLock::StoreKeyLock(fs::path dir) : dir_(std::move(dir)) {
  {
    std::ofstream owner(dir_ / kOwnerFile, std::ios::trunc);
    owner << hostName() << ' ' << getpid() << '\n';
  }
  thread_ = std::thread([this] { heartbeat(); });
}

StoreKeyLock::~StoreKeyLock() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  thread_.join();
  std::error_code ignored;
  fs::remove_all(dir_, ignored);
}

void StoreKeyLock::heartbeat() {
  std::unique_lock lock(mutex_);
  while (!wake_.wait_for(lock, kLockHeartbeat, [this] { return stopping_; })) {
    std::error_code ignored;
    fs::last_write_time(dir_ / kOwnerFile, fs::file_time_type::clock::now(), ignored);
  }
}

std::string StoreKeyLock::holderOf(const fs::path& lock_dir) {
  const std::optional<Owner> owner = readOwner(lock_dir);
  return owner ? fmt::format("{}:{}", owner->host, owner->pid) : std::string();
}

}  // namespace gib::ref
